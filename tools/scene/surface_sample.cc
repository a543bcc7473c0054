#include "tools/scene/surface_sample.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <unordered_set>

#include "tools/scene/parallel.h"
#include "tools/scene/renderer.h"

namespace msp {
namespace scene {
uint64_t VoxelKey(const Eigen::Vector3d& p, double spacing) {
  constexpr double kHalfCell = 0.5;
  constexpr int64_t kBias = 1 << 20;
  constexpr uint64_t kMask = (1u << 21) - 1;
  uint64_t key = 0;
  for (int k = 0; k < 3; ++k) {
    const int64_t v = static_cast<int64_t>(std::floor(p[k] / spacing + kHalfCell)) + kBias;
    key = (key << 21) | (static_cast<uint64_t>(v) & kMask);
  }
  return key;
}

void SetBoundingBox(SurfaceSample* sample) {
  if (sample->points.empty()) return;
  sample->bbox_min = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  sample->bbox_max = Eigen::Vector3d::Constant(std::numeric_limits<double>::lowest());
  for (const Eigen::Vector3f& p : sample->points) {
    sample->bbox_min = sample->bbox_min.cwiseMin(p.cast<double>());
    sample->bbox_max = sample->bbox_max.cwiseMax(p.cast<double>());
  }
}

SurfaceSample SampleVisibleSurface(const Scene& scene, const std::vector<PinholeView>& views,
                                   const std::vector<RenderedView>& rendered, double spacing) {
  SurfaceSample sample;
  std::unordered_set<uint64_t> occupied;
  for (size_t v = 0; v < views.size(); ++v) {
    const PinholeView& view = views[v];
    const DenseMap& depth = rendered[v].depth;
    const DenseMap& normal = rendered[v].normal;
    const Eigen::Matrix3d Rt = view.R.transpose();
    for (int row = 0; row < depth.height; ++row) {
      for (int col = 0; col < depth.width; ++col) {
        const double d = depth.At(row, col);
        if (!(d > 0.0)) continue;
        const Eigen::Vector3d X = Rt * (view.CameraPoint(col, row, d) - view.t);
        if (!occupied.insert(VoxelKey(X, spacing)).second) continue;
        const Eigen::Vector3d n(normal.At(row, col, 0), normal.At(row, col, 1),
                                normal.At(row, col, 2));
        sample.points.push_back(X.cast<float>());
        sample.normals.push_back((Rt * n).normalized().cast<float>());
      }
    }
  }
  // Visibility is counted for the stored float position (what the evaluator
  // sees); its rounding (and that of the float depth it came from) is well
  // inside IsVisible's tolerance.
  const int num_points = static_cast<int>(sample.points.size());
  sample.num_views.assign(num_points, 0);
  constexpr int kChunk = 4096;
  ParallelIndices((num_points + kChunk - 1) / kChunk, [&](int chunk) {
    const int end = std::min(num_points, (chunk + 1) * kChunk);
    for (int i = chunk * kChunk; i < end; ++i) {
      const Eigen::Vector3d p = sample.points[i].cast<double>();
      int count = 0;
      for (const PinholeView& view : views) count += IsVisible(scene, view, p) ? 1 : 0;
      sample.num_views[i] = static_cast<uint8_t>(std::min(count, 255));
    }
  });
  SetBoundingBox(&sample);
  return sample;
}

void WriteSurfacePly(const std::string& path, const SurfaceSample& sample) {
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot write " + path);
  file << "ply\nformat binary_little_endian 1.0\n"
       << "comment ground-truth surface sample; num_views = views that see the point\n"
       << "element vertex " << sample.points.size() << "\n"
       << "property float x\nproperty float y\nproperty float z\n"
       << "property float nx\nproperty float ny\nproperty float nz\n"
       << "property uchar num_views\nend_header\n";
  static_assert(sizeof(float) == 4, "PLY float is 32-bit");
  for (size_t i = 0; i < sample.points.size(); ++i) {
    const float values[6] = {sample.points[i].x(),  sample.points[i].y(),  sample.points[i].z(),
                             sample.normals[i].x(), sample.normals[i].y(), sample.normals[i].z()};
    // The generator targets little-endian hosts (x86-64, arm64), as COLMAP does.
    file.write(reinterpret_cast<const char*>(values), sizeof(values));
    file.put(static_cast<char>(sample.num_views[i]));
  }
  if (!file) throw std::runtime_error("failed writing " + path);
}

}  // namespace scene
}  // namespace msp
