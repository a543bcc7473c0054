// COLMAP-style filtering of the final maps: a pixel is kept when enough source
// views agree with its plane photometrically (NCC), see it from a wide enough
// angle and, in geometric passes, reproject consistently.
#pragma once

#include <cmath>

#include "core/patch_match/patch_match_kernel.h"
#include "core/patch_match/window_texture.h"

namespace msp {
namespace core {

struct FilterParams {
  float min_ncc;                  // filter_min_ncc
  float min_triangulation_angle;  // radians
  int min_num_consistent;         // already clamped to the number of sources
  float geom_max_error;           // filter_geom_consistency_max_cost, pixels
  // 1: in geometric passes a weakly textured pixel (window_texture.h), whose
  // NCC is noise, counts the views that agree geometrically, without the NCC test.
  int textureless_by_geometry = 0;
};

// Angle at X between the rays from the two camera centres.
MSP_HD float TriangulationAngle(Vec3 center_a, Vec3 center_b, Vec3 X) {
  const Vec3 a = Normalized(center_a - X);
  const Vec3 b = Normalized(center_b - X);
  return acosf(Clamp(Dot(a, b), -1.0f, 1.0f));
}

// Number of source views consistent with the pixel's plane.
MSP_HD int CountConsistentViews(const PassParams& p, const FilterParams& f, int col, int row) {
  const PlaneHypothesis h = p.state.Get(p.state.Index(col, row));
  if (!(h.depth > 0.0f)) return 0;
  const PreparedPlane plane = PreparePlane(p, col, row, h);
  if (!plane.valid) return 0;
  const Vec3 X = CamToWorld(p.ref_camera, BackProject(p.ref_camera, static_cast<float>(col),
                                                      static_cast<float>(row), h.depth));
  RefWindow w;
  PrepareWindow(p, col, row, &w);
  const bool by_geometry =
      f.textureless_by_geometry && p.geometric && IsWeaklyTextured(p, col, row);
  int count = 0;
  for (int j = 0; j < p.num_src; ++j) {
    const SourceView& s = p.src[j];
    if (TriangulationAngle(p.ref_camera.center, s.camera.center, X) < f.min_triangulation_angle) {
      continue;
    }
    if (by_geometry && s.depth.data == nullptr) continue;
    if (!by_geometry && 1.0f - PhotometricViewCost(p, w, j, plane) < f.min_ncc) continue;
    if (p.geometric && s.depth.data != nullptr &&
        ReprojectionError(p.ref_camera, s.camera, s.depth, col, row, h.depth,
                          f.geom_max_error + 1.0f) > f.geom_max_error) {
      continue;
    }
    ++count;
  }
  return count;
}

}  // namespace core
}  // namespace msp
