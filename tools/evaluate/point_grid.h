// Fixed-radius neighbour queries on a point set by voxel hashing: cells of
// the query radius, so a query visits the 27 cells around it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace msp {
namespace eval {

class PointGrid {
 public:
  // Keeps a pointer to `points`, which must outlive the grid. radius > 0.
  PointGrid(const std::vector<Eigen::Vector3f>& points, double radius);

  // True when some point lies within `radius` (inclusive) of q.
  bool HasNeighbor(const Eigen::Vector3f& q) const;

 private:
  struct Range {
    uint32_t begin = 0;
    uint32_t end = 0;
  };
  uint64_t Key(int64_t x, int64_t y, int64_t z) const;
  void Cell(const Eigen::Vector3f& p, int64_t c[3]) const;

  const std::vector<Eigen::Vector3f>& points_;
  double radius_;
  std::vector<uint32_t> order_;  // point indices sorted by cell key
  std::unordered_map<uint64_t, Range> cells_;
};

}  // namespace eval
}  // namespace msp
