// Normals from the surface (docs/method.md section 5.2). A textureless pixel
// can hold the right depth (from propagation, a segment plane or the other
// views' geometry) with almost any normal: its window costs the same for all
// of them, and the geometric term only sees depth. Fusion rejects points whose
// normals disagree across views, so such a pixel takes the normal of the
// surface its neighbours' depths describe instead.
#pragma once

#include <cmath>

#include "core/math/camera.h"
#include "core/math/hd.h"
#include "core/math/vec.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// Pixels from the centre to each of the four neighbours spanning the surface.
constexpr int kSurfaceNormalSpan = 3;
// A neighbour whose depth differs from the centre's by more than this share
// lies across a depth edge: no surface normal there.
constexpr float kSurfaceMaxDepthJump = 0.05f;

// The 3D point (camera frame) of pixel (col, row) in `depth`, false when it
// is outside the image, has no depth or jumps from `centre_depth`.
MSP_HD bool SurfacePoint(const Camera& cam, const PixelStateView& s, int col, int row,
                         float centre_depth, Vec3* X) {
  if (col < 0 || row < 0 || col >= s.width || row >= s.height) return false;
  const float d = s.depth[s.Index(col, row)];
  if (!(d > 0.0f) || fabsf(d - centre_depth) > kSurfaceMaxDepthJump * centre_depth) return false;
  *X = BackProject(cam, static_cast<float>(col), static_cast<float>(row), d);
  return true;
}

// Normal of the surface through the depths around (col, row): the cross
// product of its horizontal and vertical chords, facing the camera. Falls
// back to one-sided chords at borders and edges; false when a direction has
// no chord.
MSP_HD bool SurfaceNormalAt(const Camera& cam, const PixelStateView& s, int col, int row,
                            Vec3* normal) {
  const float d = s.depth[s.Index(col, row)];
  if (!(d > 0.0f)) return false;
  const Vec3 centre = BackProject(cam, static_cast<float>(col), static_cast<float>(row), d);
  const int k = kSurfaceNormalSpan;
  Vec3 left, right, up, down;
  const bool has_left = SurfacePoint(cam, s, col - k, row, d, &left);
  const bool has_right = SurfacePoint(cam, s, col + k, row, d, &right);
  const bool has_up = SurfacePoint(cam, s, col, row - k, d, &up);
  const bool has_down = SurfacePoint(cam, s, col, row + k, d, &down);
  if (!(has_left || has_right) || !(has_up || has_down)) return false;
  const Vec3 horizontal = (has_right ? right : centre) - (has_left ? left : centre);
  const Vec3 vertical = (has_down ? down : centre) - (has_up ? up : centre);
  const Vec3 n = Cross(horizontal, vertical);
  const float len = Norm(n);
  if (!(len > 0.0f)) return false;
  *normal = FaceCamera(cam, col, row, (1.0f / len) * n);
  return true;
}

}  // namespace core
}  // namespace msp
