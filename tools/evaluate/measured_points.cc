#include "tools/evaluate/measured_points.h"

#include <cmath>
#include <limits>

namespace msp {
namespace eval {
namespace {

// The ground-truth pixel `point` projects to in `view` (nearest pixel:
// integer indices are image points, no +0.5, as in COLMAP's dense maps) and
// the point's depth there; false when it is behind the camera or outside.
bool ProjectTo(const MeasuredView& view, const Eigen::Vector3f& point, int* c, int* r,
               float* depth) {
  const core::Vec3 X = core::WorldToCam(view.camera, core::Vec3{point.x(), point.y(), point.z()});
  float col = 0.0f, row = 0.0f;
  if (!core::ProjectCamPoint(view.camera, X, &col, &row)) return false;
  const long cl = std::lround(col), rl = std::lround(row);
  if (cl < 0 || rl < 0 || cl >= view.depth.width || rl >= view.depth.height) return false;
  *c = static_cast<int>(cl);
  *r = static_cast<int>(rl);
  *depth = X.z;
  return true;
}

bool MeasuredIn(const MeasuredView& view, const Eigen::Vector3f& point, bool zero_is_empty) {
  int c = 0, r = 0;
  float depth = 0.0f;
  if (!ProjectTo(view, point, &c, &r, &depth)) return false;
  return zero_is_empty || view.depth.At(r, c) > 0.0f;
}

}  // namespace

std::vector<uint8_t> MeasuredPoints(const std::vector<Eigen::Vector3f>& points,
                                    const std::vector<MeasuredView>& views, bool zero_is_empty) {
  std::vector<uint8_t> judged(points.size(), 0);
  for (size_t i = 0; i < points.size(); ++i) {
    for (const MeasuredView& view : views) {
      if (MeasuredIn(view, points[i], zero_is_empty)) {
        judged[i] = 1;
        break;
      }
    }
  }
  return judged;
}

std::vector<uint8_t> OnTexturelessSurface(const std::vector<Eigen::Vector3f>& points,
                                          const std::vector<MeasuredView>& views) {
  std::vector<uint8_t> textureless(points.size(), 0);
  for (size_t i = 0; i < points.size(); ++i) {
    float best = std::numeric_limits<float>::infinity();
    for (const MeasuredView& view : views) {
      int c = 0, r = 0;
      float depth = 0.0f;
      if (view.textureless.empty() || !ProjectTo(view, points[i], &c, &r, &depth)) continue;
      const float gt = view.depth.At(r, c);
      if (!(gt > 0.0f)) continue;
      const float difference = std::fabs(depth - gt) / gt;
      if (difference > best) continue;
      best = difference;
      textureless[i] = view.textureless.at<uint8_t>(r, c) > 0 ? 1 : 0;
    }
  }
  return textureless;
}

}  // namespace eval
}  // namespace msp
