#include "tools/scene/surface_ids.h"

#include <cstdint>
#include <stdexcept>
#include <string>

#include "tools/scene/renderer.h"

namespace msp {
namespace scene {
namespace {

constexpr int kMaxId = 65535;  // 16-bit labels

int CheckedId(int64_t id, int level) {
  if (id > kMaxId) {
    throw std::runtime_error("ideal mask level " + std::to_string(level) +
                             ": the scene has too many surfaces for 16-bit ids");
  }
  return static_cast<int>(id);
}

}  // namespace

int SurfaceId(const Scene& scene, const Hit& hit, int level) {
  const int64_t shape = hit.shape;
  const int64_t face = shape * kMaxShapeFaces + hit.face;
  switch (level) {
    case 0:
      return CheckedId(1 + shape, level);
    case 1:
      return CheckedId(1 + face, level);
    case 2: {
      const int64_t paints = 2 * static_cast<int64_t>(scene.materials.size());
      const int64_t paint = 2 * hit.material + scene.Paint(hit.material, hit.point);
      return CheckedId(1 + face * paints + paint, level);
    }
  }
  throw std::runtime_error("ideal mask level " + std::to_string(level) + " does not exist");
}

IdealMasks RenderIdealMasks(const Scene& scene, const PinholeView& view) {
  IdealMasks masks;
  for (cv::Mat& mask : masks) mask = cv::Mat(view.height, view.width, CV_16UC1, cv::Scalar(0));
  for (int row = 0; row < view.height; ++row) {
    for (int col = 0; col < view.width; ++col) {
      Hit hit;
      double depth = 0.0;
      Eigen::Vector3d normal;
      if (!GroundTruthAt(scene, view, col, row, &hit, &depth, &normal)) continue;
      for (int level = 0; level < kNumIdealMaskLevels; ++level) {
        masks[level].at<uint16_t>(row, col) = static_cast<uint16_t>(SurfaceId(scene, hit, level));
      }
    }
  }
  return masks;
}

}  // namespace scene
}  // namespace msp
