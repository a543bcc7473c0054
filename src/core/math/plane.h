// Per-pixel plane hypotheses: depth (camera z) at the pixel plus a unit normal
// in the reference camera frame, facing the camera (dot(n, ray) < 0).
#pragma once

#include <cmath>

#include "core/math/camera.h"
#include "core/math/hd.h"
#include "core/math/rng.h"
#include "core/math/vec.h"

namespace msp {
namespace core {

struct PlaneHypothesis {
  float depth;
  Vec3 normal;
};

// Distance term d' of the plane n^T X + d' = 0 through the pixel's 3D point;
// positive for a camera-facing normal.
MSP_HD float PlaneDistance(const Camera& cam, int col, int row, const PlaneHypothesis& h) {
  return -Dot(h.normal,
              BackProject(cam, static_cast<float>(col), static_cast<float>(row), h.depth));
}

// Depth (camera z) where `ray` (z = 1, as ViewRay) meets the plane n^T X + dist = 0.
// Returns 0 when the ray is parallel to the plane or hits it behind the camera.
MSP_HD float DepthOnRay(Vec3 normal, float dist, Vec3 ray) {
  const float denom = Dot(normal, ray);
  if (fabsf(denom) < 1e-12f) return 0.0f;
  const float depth = -dist / denom;
  return depth > 0.0f ? depth : 0.0f;
}

// The same on the ray of pixel (col, row).
MSP_HD float DepthOnPlane(const Camera& cam, Vec3 normal, float dist, float col, float row) {
  return DepthOnRay(normal, dist, ViewRay(cam, col, row));
}

// Depth at pixel q of the plane hypothesis h held by pixel p.
MSP_HD float PropagatedDepth(const Camera& cam, int p_col, int p_row, const PlaneHypothesis& h,
                             int q_col, int q_row) {
  return DepthOnPlane(cam, h.normal, PlaneDistance(cam, p_col, p_row, h), static_cast<float>(q_col),
                      static_cast<float>(q_row));
}

// Flips n to face the camera through pixel (col, row).
MSP_HD Vec3 FaceCamera(const Camera& cam, int col, int row, Vec3 n) {
  return Dot(n, ViewRay(cam, static_cast<float>(col), static_cast<float>(row))) > 0.0f ? -n : n;
}

// Uniformly distributed unit normal on the hemisphere facing the camera
// (Marsaglia's method on the sphere, then flipped towards the camera).
MSP_HD Vec3 RandomNormal(const Camera& cam, int col, int row, Rng* rng) {
  float u, v, s;
  int guard = 0;
  do {
    u = rng->Uniform(-1.0f, 1.0f);
    v = rng->Uniform(-1.0f, 1.0f);
    s = u * u + v * v;
  } while ((s >= 1.0f || s < 1e-6f) && ++guard < 16);
  if (s >= 1.0f || s < 1e-6f) return Vec3{0.0f, 0.0f, -1.0f};
  const float f = 2.0f * sqrtf(1.0f - s);
  return FaceCamera(cam, col, row, Normalized(Vec3{u * f, v * f, 1.0f - 2.0f * s}));
}

// Normal rotated by a random small amount (each component perturbed by up to
// max_angle radians), kept facing the camera; falls back to n when the
// perturbation would turn it away.
MSP_HD Vec3 PerturbNormal(const Camera& cam, int col, int row, Vec3 n, float max_angle, Rng* rng) {
  const Vec3 ray = ViewRay(cam, static_cast<float>(col), static_cast<float>(row));
  for (int attempt = 0; attempt < 3; ++attempt) {
    const float a1 = rng->Uniform(-max_angle, max_angle);
    const float a2 = rng->Uniform(-max_angle, max_angle);
    const float a3 = rng->Uniform(-max_angle, max_angle);
    // Small-angle rotation: n + a x n, renormalised.
    const Vec3 p = Normalized(n + Cross(Vec3{a1, a2, a3}, n));
    if (Dot(p, ray) < 0.0f) return p;
  }
  return n;
}

// Random hypothesis: depth uniform in [depth_min, depth_max], normal random.
MSP_HD PlaneHypothesis RandomHypothesis(const Camera& cam, int col, int row, float depth_min,
                                        float depth_max, Rng* rng) {
  PlaneHypothesis h;
  h.depth = rng->Uniform(depth_min, depth_max);
  h.normal = RandomNormal(cam, col, row, rng);
  return h;
}

}  // namespace core
}  // namespace msp
