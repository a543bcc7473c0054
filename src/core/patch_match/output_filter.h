// COLMAP-style filtering of the final maps: a pixel is kept when enough source
// views agree with its plane photometrically (NCC), see it from a wide enough
// angle and, in geometric passes, reproject consistently.
#pragma once

#include <cmath>

#include "core/patch_match/geometric_cost.h"
#include "core/patch_match/map_stage.h"
#include "core/patch_match/patch_match_kernel.h"
#include "core/patch_match/window_texture.h"

namespace msp {
namespace core {

struct FilterParams {
  float min_ncc;                  // filter_min_ncc
  float min_triangulation_angle;  // radians
  int min_num_consistent;         // already clamped to the number of sources
  float geom_max_error;           // filter_geom_consistency_max_cost, pixels
  // > 0: a source agrees when its depth map holds the pixel's point within
  // this relative depth (DepthDisagreement), instead of the reprojection test.
  float max_depth_error = 0.0f;
  // > 0, in geometric passes: a pixel is also kept when a single source passes
  // every test with the depth agreeing within this (tighter) relative error.
  float single_view_max_depth_error = 0.0f;
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

// What the filter's tests say of one source view for a pixel's plane.
struct ViewTests {
  bool angle = false;        // triangulation angle >= min_triangulation_angle
  bool photometric = false;  // NCC >= min_ncc (or, by geometry, a source depth map exists)
  bool geometric = false;    // the depths agree (true outside geometric passes)
  MSP_HD bool All() const { return angle && photometric && geometric; }
};

// The pixel's plane prepared once for the tests of every view.
struct FilterPixel {
  bool valid = false;
  PlaneHypothesis h;
  PreparedPlane plane;
  Vec3 X;  // world point
  RefWindow window;
  bool by_geometry = false;
};

// With `geometry_only`, every pixel is judged as a weakly textured one under
// textureless_by_geometry: by the sources' depth maps, without NCC.
MSP_HD FilterPixel PrepareFilterPixel(const PassParams& p, const FilterParams& f, int col, int row,
                                      bool geometry_only = false) {
  FilterPixel q;
  q.h = p.state.Get(p.state.Index(col, row));
  if (!(q.h.depth > 0.0f)) return q;
  q.plane = PreparePlane(p, col, row, q.h);
  if (!q.plane.valid) return q;
  q.X = CamToWorld(p.ref_camera, BackProject(p.ref_camera, static_cast<float>(col),
                                             static_cast<float>(row), q.h.depth));
  q.by_geometry =
      geometry_only || (f.textureless_by_geometry && p.geometric && IsWeaklyTextured(p, col, row));
  if (!q.by_geometry) PrepareWindow(p, col, row, &q.window);
  q.valid = true;
  return q;
}

// The tests of source `j`. With `all` false it stops at the first failed test
// (the filter's count); with `all` true every test is run, to say which failed.
MSP_HD ViewTests TestView(const PassParams& p, const FilterParams& f, const FilterPixel& q, int j,
                          int col, int row, bool all) {
  ViewTests t;
  const SourceView& s = p.src[j];
  t.angle =
      TriangulationAngle(p.ref_camera.center, s.camera.center, q.X) >= f.min_triangulation_angle;
  if (!t.angle && !all) return t;
  t.photometric = q.by_geometry ? s.depth.data != nullptr
                                : 1.0f - PhotometricViewCost(p, q.window, j, q.plane) >= f.min_ncc;
  if (!t.photometric && !all) return t;
  if (!(p.geometric && s.depth.data != nullptr)) {
    t.geometric = true;
  } else if (f.max_depth_error > 0.0f) {
    t.geometric = DepthDisagreement(p.ref_camera, s.camera, s.depth, col, row, q.h.depth,
                                    2.0f * f.max_depth_error) <= f.max_depth_error;
  } else {
    t.geometric = ReprojectionError(p.ref_camera, s.camera, s.depth, col, row, q.h.depth,
                                    f.geom_max_error + 1.0f) <= f.geom_max_error;
  }
  return t;
}

// Number of source views that pass every test for the prepared pixel `q`.
MSP_HD int CountPassingViews(const PassParams& p, const FilterParams& f, const FilterPixel& q,
                             int col, int row) {
  if (!q.valid) return 0;
  int count = 0;
  for (int j = 0; j < p.num_src; ++j) count += TestView(p, f, q, j, col, row, false).All() ? 1 : 0;
  return count;
}

// Number of source views consistent with the pixel's plane.
MSP_HD int CountConsistentViews(const PassParams& p, const FilterParams& f, int col, int row) {
  return CountPassingViews(p, f, PrepareFilterPixel(p, f, col, row), col, row);
}

// Whether one source alone vouches for the prepared pixel `q`: it has a depth
// map, and passes every test with that map agreeing within
// single_view_max_depth_error. A weakly textured floor or wall seen well by
// one other frame only is as right as one two frames confirm, if the
// agreement is tight enough (docs/method.md section 2.9). A source without a
// depth map (not run yet) agrees by default in the count, so it cannot vouch.
MSP_HD bool OneViewVouches(const PassParams& p, const FilterParams& f, const FilterPixel& q,
                           int col, int row) {
  if (!(f.single_view_max_depth_error > 0.0f && p.geometric && q.valid)) return false;
  FilterParams strict = f;
  strict.max_depth_error = f.single_view_max_depth_error;
  for (int j = 0; j < p.num_src; ++j) {
    if (p.src[j].depth.data != nullptr && TestView(p, strict, q, j, col, row, false).All()) {
      return true;
    }
  }
  return false;
}

// The filter's verdict: enough consistent views, or one that vouches alone.
MSP_HD bool FilterKeeps(const PassParams& p, const FilterParams& f, int col, int row) {
  const FilterPixel q = PrepareFilterPixel(p, f, col, row);
  return CountPassingViews(p, f, q, col, row) >= f.min_num_consistent ||
         OneViewVouches(p, f, q, col, row);
}

// Number of sources whose depth maps agree with the pixel's depth (the
// filter's geometric test), at a triangulation angle of at least
// min_triangulation_angle (geometric passes; 0 otherwise): the other views'
// evidence for its plane, without the photometric test.
MSP_HD int CountAgreeingViews(const PassParams& p, const FilterParams& f, int col, int row) {
  if (!p.geometric) return 0;
  return CountPassingViews(p, f, PrepareFilterPixel(p, f, col, row, true), col, row);
}

// The stage of a pixel with a plane that the filter keeps or removes: which
// single test, dropped, would let the pixel pass.
MSP_HD int FilterStage(const PassParams& p, const FilterParams& f, int col, int row) {
  const FilterPixel q = PrepareFilterPixel(p, f, col, row);
  if (!q.valid) return kStageNoPlane;
  int all = 0, no_angle = 0, no_photometric = 0, no_geometric = 0;
  for (int j = 0; j < p.num_src; ++j) {
    const ViewTests t = TestView(p, f, q, j, col, row, true);
    all += t.All() ? 1 : 0;
    no_angle += t.photometric && t.geometric ? 1 : 0;
    no_photometric += t.angle && t.geometric ? 1 : 0;
    no_geometric += t.angle && t.photometric ? 1 : 0;
  }
  const int n = f.min_num_consistent;
  if (all >= n || OneViewVouches(p, f, q, col, row)) return kStageKept;
  if (no_angle >= n) return kStageFilterAngle;
  if (no_photometric >= n) return kStageFilterPhotometric;
  if (no_geometric >= n) return kStageFilterGeometric;
  return kStageFilterSeveral;
}

}  // namespace core
}  // namespace msp
