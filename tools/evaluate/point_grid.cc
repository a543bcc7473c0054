#include "tools/evaluate/point_grid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace msp {
namespace eval {
namespace {

// 21 bits per axis: cell coordinates within +-2^20 (a million cells per side).
constexpr int64_t kCellBias = int64_t{1} << 20;
constexpr uint64_t kCellMask = (uint64_t{1} << 21) - 1;

}  // namespace

PointGrid::PointGrid(const std::vector<Eigen::Vector3f>& points, double radius)
    : points_(points), radius_(radius) {
  std::vector<uint64_t> keys(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    int64_t c[3];
    Cell(points[i], c);
    keys[i] = Key(c[0], c[1], c[2]);
  }
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0u);
  std::sort(order_.begin(), order_.end(),
            [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
  for (uint32_t i = 0; i < order_.size();) {
    uint32_t j = i;
    while (j < order_.size() && keys[order_[j]] == keys[order_[i]]) ++j;
    cells_[keys[order_[i]]] = Range{i, j};
    i = j;
  }
}

uint64_t PointGrid::Key(int64_t x, int64_t y, int64_t z) const {
  return ((static_cast<uint64_t>(x + kCellBias) & kCellMask) << 42) |
         ((static_cast<uint64_t>(y + kCellBias) & kCellMask) << 21) |
         (static_cast<uint64_t>(z + kCellBias) & kCellMask);
}

void PointGrid::Cell(const Eigen::Vector3f& p, int64_t c[3]) const {
  for (int k = 0; k < 3; ++k) c[k] = static_cast<int64_t>(std::floor(p[k] / radius_));
}

bool PointGrid::HasNeighbor(const Eigen::Vector3f& q) const {
  int64_t c[3];
  Cell(q, c);
  const double r2 = radius_ * radius_;
  for (int64_t dx = -1; dx <= 1; ++dx) {
    for (int64_t dy = -1; dy <= 1; ++dy) {
      for (int64_t dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find(Key(c[0] + dx, c[1] + dy, c[2] + dz));
        if (it == cells_.end()) continue;
        for (uint32_t i = it->second.begin; i < it->second.end; ++i) {
          if ((points_[order_[i]] - q).cast<double>().squaredNorm() <= r2) return true;
        }
      }
    }
  }
  return false;
}

}  // namespace eval
}  // namespace msp
