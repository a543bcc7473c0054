#include "tools/measured_points.h"

#include <cmath>

namespace msp {
namespace eval {
namespace {

bool MeasuredIn(const MeasuredView& view, const Eigen::Vector3f& point, bool zero_is_empty) {
  const core::Vec3 X = core::WorldToCam(view.camera, core::Vec3{point.x(), point.y(), point.z()});
  float col = 0.0f, row = 0.0f;
  if (!core::ProjectCamPoint(view.camera, X, &col, &row)) return false;
  // The nearest pixel: integer indices are image points (no +0.5), as in
  // COLMAP's dense maps.
  const long c = std::lround(col), r = std::lround(row);
  if (c < 0 || r < 0 || c >= view.depth.width || r >= view.depth.height) return false;
  return zero_is_empty || view.depth.At(static_cast<int>(r), static_cast<int>(c)) > 0.0f;
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

}  // namespace eval
}  // namespace msp
