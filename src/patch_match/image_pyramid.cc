#include "patch_match/image_pyramid.h"

#include <algorithm>
#include <cmath>

#include "core/math/plane.h"

namespace msp {

int NumHalvings(int width, int height, int coarsest_size) {
  int halvings = 0;
  int side = std::max(width, height);
  while (side > coarsest_size) {
    side /= 2;
    ++halvings;
  }
  return halvings;
}

DenseMap DownsampleHalf(const DenseMap& image) {
  DenseMap out(image.width / 2, image.height / 2, image.channels);
  for (int c = 0; c < image.channels; ++c) {
    for (int r = 0; r < out.height; ++r) {
      for (int col = 0; col < out.width; ++col) {
        out.At(r, col, c) =
            0.25f * (image.At(2 * r, 2 * col, c) + image.At(2 * r, 2 * col + 1, c) +
                     image.At(2 * r + 1, 2 * col, c) + image.At(2 * r + 1, 2 * col + 1, c));
      }
    }
  }
  return out;
}

core::Camera HalveCamera(const core::Camera& camera, int new_width, int new_height) {
  core::Camera out = camera;
  out.width = new_width;
  out.height = new_height;
  out.fx = camera.fx * 0.5f;
  out.fy = camera.fy * 0.5f;
  out.cx = (camera.cx - 0.5f) * 0.5f;
  out.cy = (camera.cy - 0.5f) * 0.5f;
  return out;
}

PixelState UpsampleState(const PixelState& coarse, const core::Camera& coarse_cam,
                         const core::Camera& fine_cam) {
  PixelState fine(fine_cam.width, fine_cam.height);
  const core::PixelStateView fv = fine.View();
  const float sx = static_cast<float>(coarse_cam.width) / fine_cam.width;
  const float sy = static_cast<float>(coarse_cam.height) / fine_cam.height;
  if (!coarse.edges.empty()) fine.edges.assign(fine.depth.size(), 0);
  for (int r = 0; r < fine.height; ++r) {
    const int cr = std::min(coarse.height - 1, static_cast<int>(r * sy));
    for (int c = 0; c < fine.width; ++c) {
      const int cc = std::min(coarse.width - 1, static_cast<int>(c * sx));
      const int ci = cr * coarse.width + cc;
      const int fi = fv.Index(c, r);
      const core::PlaneHypothesis h = coarse.Plane(ci);
      fine.mask[fi] = coarse.mask[ci];
      if (!fine.edges.empty()) fine.edges[fi] = coarse.edges[ci];  // nearest: edges never blend
      if (!(h.depth > 0.0f)) continue;
      // The plane is a 3D object: its distance term is the same in both
      // cameras (same pose), so intersect it with the fine pixel's ray.
      const float dist = core::PlaneDistance(coarse_cam, cc, cr, h);
      const float depth = core::DepthOnPlane(fine_cam, h.normal, dist, static_cast<float>(c),
                                             static_cast<float>(r));
      if (depth > 0.0f) fv.Set(fi, core::PlaneHypothesis{depth, h.normal});
    }
  }
  return fine;
}

}  // namespace msp
