#include "tools/rgbd/measured_surface.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "tools/evaluate/edge_regions.h"
#include "tools/scene/parallel.h"

namespace msp {
namespace rgbd {
namespace {

// Samples per task of the visibility count.
constexpr int kChunk = 4096;
constexpr int kMaxViewCount = 255;  // the PLY's uchar num_views

bool SeenBy(const scene::PinholeView& view, const DenseMap& depth, const Eigen::Vector3d& X) {
  double col = 0.0, row = 0.0, z = 0.0;
  if (!view.Project(X, &col, &row, &z)) return false;
  const long c = std::lround(col), r = std::lround(row);
  if (c < 0 || r < 0 || c >= depth.width || r >= depth.height) return false;
  const double d = depth.At(static_cast<int>(r), static_cast<int>(c));
  return d > 0.0 && std::abs(d - z) <= eval::kDepthEdgeJump * std::min(d, z);
}

}  // namespace

scene::SurfaceSample SampleMeasuredSurface(const std::vector<scene::PinholeView>& views,
                                           const std::vector<DenseMap>& depths,
                                           const std::vector<DenseMap>& normals, double spacing) {
  scene::SurfaceSample sample;
  std::unordered_set<uint64_t> occupied;
  for (size_t v = 0; v < views.size(); ++v) {
    const scene::PinholeView& view = views[v];
    const Eigen::Matrix3d Rt = view.R.transpose();
    for (int row = 0; row < depths[v].height; ++row) {
      for (int col = 0; col < depths[v].width; ++col) {
        const double d = depths[v].At(row, col);
        if (!(d > 0.0)) continue;
        const Eigen::Vector3d X = Rt * (view.CameraPoint(col, row, d) - view.t);
        if (!occupied.insert(scene::VoxelKey(X, spacing)).second) continue;
        const Eigen::Vector3d n(normals[v].At(row, col, 0), normals[v].At(row, col, 1),
                                normals[v].At(row, col, 2));
        sample.points.push_back(X.cast<float>());
        sample.normals.push_back((Rt * n).cast<float>());
      }
    }
  }
  const int num_points = static_cast<int>(sample.points.size());
  sample.num_views.assign(num_points, 0);
  scene::ParallelIndices((num_points + kChunk - 1) / kChunk, [&](int chunk) {
    const int end = std::min(num_points, (chunk + 1) * kChunk);
    for (int i = chunk * kChunk; i < end; ++i) {
      const Eigen::Vector3d X = sample.points[i].cast<double>();
      int count = 0;
      for (size_t v = 0; v < views.size(); ++v) count += SeenBy(views[v], depths[v], X) ? 1 : 0;
      sample.num_views[i] = static_cast<uint8_t>(std::min(count, kMaxViewCount));
    }
  });
  scene::SetBoundingBox(&sample);
  return sample;
}

}  // namespace rgbd
}  // namespace msp
