#include "patch_match/image_pyramid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "base/parallel_for.h"
#include "core/math/plane.h"
#include "core/patch_match/joint_bilateral.h"

namespace msp {

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

namespace {

// The pixel index nearest to coordinate x, clamped to [0, size).
int NearestIndex(float x, int size) {
  return std::min(size - 1, std::max(0, static_cast<int>(std::floor(x + 0.5f))));
}

}  // namespace

PixelState UpsampleStateNearest(const PixelState& coarse, const core::Camera& coarse_cam,
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

PixelState UpsampleStateJointBilateral(const PixelState& coarse, const DenseMap& coarse_guide,
                                       const core::Camera& coarse_cam, const DenseMap& fine_guide,
                                       const core::Camera& fine_cam, int num_threads) {
  if (coarse_guide.width != coarse.width || coarse_guide.height != coarse.height ||
      fine_guide.width != fine_cam.width || fine_guide.height != fine_cam.height) {
    throw std::logic_error("UpsampleStateJointBilateral: guide and state sizes differ");
  }
  // Nearest neighbour gives the edge bits, and the pixels no plane reaches.
  PixelState fine = UpsampleStateNearest(coarse, coarse_cam, fine_cam);
  const core::PixelStateView fv = fine.View();
  // Distance terms of the coarse planes, each shared by ~36 fine pixels.
  std::vector<float> dist(coarse.depth.size(), 0.0f);
  for (int cr = 0; cr < coarse.height; ++cr) {
    for (int cc = 0; cc < coarse.width; ++cc) {
      const int ci = cr * coarse.width + cc;
      const core::PlaneHypothesis h = coarse.Plane(ci);
      if (h.depth > 0.0f) dist[ci] = core::PlaneDistance(coarse_cam, cc, cr, h);
    }
  }
  // Fine pixels per coarse pixel (2). The cameras differ only in K, so a
  // fine pixel's coarse position (uc, vc) follows from the intrinsics.
  const float ax = fine_cam.fx / coarse_cam.fx;
  const float ay = fine_cam.fy / coarse_cam.fy;
  ParallelFor(0, fine.height, num_threads, [&](int r) {
    const float vc = coarse_cam.cy + (r - fine_cam.cy) / ay;
    const int cr = NearestIndex(vc, coarse.height);
    for (int c = 0; c < fine.width; ++c) {
      const float uc = coarse_cam.cx + (c - fine_cam.cx) / ax;
      const int cc = NearestIndex(uc, coarse.width);
      const float guide = fine_guide.At(r, c);
      float depth[core::kJbuNumCandidates], weight[core::kJbuNumCandidates];
      int index[core::kJbuNumCandidates];
      int n = 0;
      for (int k = 0; k < core::kJbuNumCandidates; ++k) {
        const int qc = cc + core::kJbuOffsetCol[k];
        const int qr = cr + core::kJbuOffsetRow[k];
        if (qc < 0 || qr < 0 || qc >= coarse.width || qr >= coarse.height) continue;
        const int qi = qr * coarse.width + qc;
        if (!(coarse.depth[qi] > 0.0f)) continue;
        const float d = core::DepthOnPlane(fine_cam, coarse.Plane(qi).normal, dist[qi],
                                           static_cast<float>(c), static_cast<float>(r));
        if (!(d > 0.0f)) continue;
        weight[n] = core::JointBilateralWeight((qc - uc) * ax, (qr - vc) * ay,
                                               guide - coarse_guide.At(qr, qc));
        depth[n] = d;
        index[n++] = qi;
      }
      const int best = core::WeightedDepthMode(depth, weight, n);
      if (best < 0) continue;
      const int fi = fv.Index(c, r);
      fv.Set(fi, core::PlaneHypothesis{depth[best], coarse.Plane(index[best]).normal});
      fine.mask[fi] = coarse.mask[index[best]];
    }
  });
  return fine;
}

}  // namespace msp
