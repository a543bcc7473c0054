// Segment planes, per pixel (docs/method.md section 2.10). A pixel of a
// textureless wall has no photometric signal to choose its plane, but its
// colour segment usually holds pixels that do (its borders, any texture on
// it), and their 3D points fix the plane of the whole segment. The host fits
// one plane per segment (src/patch_match/segment_planes.cc); here each pixel
// says how much texture its window has and takes its segment's plane when
// that costs no more than its own by a margin that only weak texture gets.
#pragma once

#include <cmath>

#include "core/math/hd.h"
#include "core/math/plane.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/patch_match_kernel.h"
#include "core/patch_match/window_texture.h"

namespace msp {
namespace core {

// The plane through `point` (camera frame) with unit normal `normal`, as the
// hypothesis of pixel (col, row); depth 0 when the pixel's ray misses it.
MSP_HD PlaneHypothesis HypothesisOnPlane(const Camera& cam, int col, int row, Vec3 normal,
                                         Vec3 point) {
  const float dist = -Dot(normal, point);
  const float depth =
      DepthOnPlane(cam, normal, dist, static_cast<float>(col), static_cast<float>(row));
  return PlaneHypothesis{depth, FaceCamera(cam, col, row, normal)};
}

// Pixel (col, row) takes `candidate` (its segment's plane) when the
// candidate's cost over the pixel's selected views is below its own plane's
// plus `margin`. Costs are computed alike for both (LocalRefinePixel's form),
// so a pixel with texture (margin 0) keeps its plane unless the candidate
// matches better; a textureless one, whose costs are noise, takes the
// segment's plane unless the views clearly reject it.
MSP_HD void OfferSegmentPlane(const PassParams& p, int col, int row,
                              const PlaneHypothesis& candidate, float margin) {
  const PixelStateView& s = p.state;
  const int i = s.Index(col, row);
  if (IsUnlit(p, i) || !DepthInRange(p, candidate.depth)) return;
  float weights[kMaxSourceViews];
  MaskWeights(p, s.mask[i], weights);
  RefWindow w;
  PrepareWindow(p, col, row, &w);
  const PlaneHypothesis cur = s.Get(i);
  const float own =
      cur.depth > 0.0f ? AggregateViewCostBelow(p, w, cur, weights, kUnboundedCost) : kMaxCost;
  const float cost = AggregateViewCostBelow(p, w, candidate, weights, own + margin);
  if (cost >= own + margin) return;
  s.Set(i, candidate);
  s.cost[i] = cost;
}

}  // namespace core
}  // namespace msp
