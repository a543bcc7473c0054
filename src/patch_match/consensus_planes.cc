#include "patch_match/consensus_planes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/parallel_for.h"
#include "core/math/rng.h"
#include "core/patch_match/segment_plane.h"
#include "core/patch_match/window_texture.h"
#include "patch_match/segment_planes.h"

namespace msp {
namespace {

// A point is on a plane when the plane's depth on its ray is within this
// share of its own: the output filter's 1 % agreement, halved, so that a
// plane gathers the points the views agree on and not their neighbours'.
constexpr float kInlierDepth = 0.005f;
// A plane claims the points within this share of depth before the next one
// is sought, so that one surface's scatter does not make a second plane.
constexpr float kClaimDepth = 0.02f;
constexpr int kMaxPlanesPerSegment = 3;
constexpr int kRefits = 2;
constexpr int kRansacIterations = 200;
// A plane holds at least this share of the region's confirmed points.
constexpr double kMinInlierShare = 0.2;
// RANSAC scores hypotheses on at most this many points (an even subsample).
constexpr size_t kMaxScoredPoints = 1024;
// A plane needs this share of the image's pixels as inliers (100 at 640x480),
// and at least kMinInliersFloor.
constexpr int kPixelsPerInlier = 3000;
constexpr int kMinInliersFloor = 12;

// Depth on `ray` (z = 1) of the plane through `point` with `normal`; 0 when
// the ray misses it in front of the camera.
float DepthOnRay(core::Vec3 normal, core::Vec3 point, core::Vec3 ray) {
  return core::DepthOnRay(normal, -core::Dot(normal, point), ray);
}

bool OnPlane(core::Vec3 normal, core::Vec3 point, core::Vec3 X, core::Vec3 ray,
             float tolerance = kInlierDepth) {
  return std::fabs(DepthOnRay(normal, point, ray) - X.z) < tolerance * X.z;
}

// Least-squares plane of the points at `indices`, normal facing the camera.
ConsensusPlane Refit(const std::vector<core::Vec3>& points, const std::vector<size_t>& indices) {
  std::vector<core::Vec3> members;
  members.reserve(indices.size());
  for (size_t k : indices) members.push_back(points[k]);
  ConsensusPlane plane;
  LeastSquaresPlane(members, &plane.normal, &plane.point);
  if (core::Dot(plane.normal, plane.point) > 0.0f) plane.normal = -1.0f * plane.normal;
  return plane;
}

}  // namespace

std::vector<ConsensusPlane> FitConsensusPlanes(const std::vector<core::Vec3>& points,
                                               const std::vector<core::Vec3>& rays, int min_inliers,
                                               uint64_t key) {
  std::vector<ConsensusPlane> planes;
  const size_t needed = std::max<size_t>(
      static_cast<size_t>(min_inliers),
      static_cast<size_t>(std::ceil(kMinInlierShare * static_cast<double>(points.size()))));
  std::vector<size_t> left(points.size());
  for (size_t k = 0; k < left.size(); ++k) left[k] = k;
  core::Rng rng = core::MakeRng(key);
  while (static_cast<int>(planes.size()) < kMaxPlanesPerSegment && left.size() >= needed) {
    const size_t stride = (left.size() + kMaxScoredPoints - 1) / kMaxScoredPoints;
    const auto pick = [&]() {
      const size_t k = static_cast<size_t>(rng.Uniform() * left.size());
      return points[left[std::min(k, left.size() - 1)]];
    };
    int best_count = 0;
    core::Vec3 best_normal{0.0f, 0.0f, 0.0f}, best_point{0.0f, 0.0f, 0.0f};
    for (int it = 0; it < kRansacIterations; ++it) {
      const core::Vec3 a = pick(), b = pick(), c = pick();
      const core::Vec3 n = core::Cross(b - a, c - a);
      const float length = core::Norm(n);
      if (!(length > 1e-9f)) continue;  // a repeated or collinear triple
      const core::Vec3 normal = (1.0f / length) * n;
      int count = 0;
      for (size_t k = 0; k < left.size(); k += stride) {
        count += OnPlane(normal, a, points[left[k]], rays[left[k]]) ? 1 : 0;
      }
      if (count > best_count) {
        best_count = count;
        best_normal = normal;
        best_point = a;
      }
    }
    if (best_count == 0) break;
    // The least-squares refit over the points within kClaimDepth, twice: a
    // refit of the narrow inlier band alone keeps the tilt of the triple
    // that chose it.
    ConsensusPlane plane;
    plane.normal = best_normal;
    plane.point = best_point;
    for (int refit = 0; refit < kRefits; ++refit) {
      std::vector<size_t> members;
      for (size_t k : left) {
        if (OnPlane(plane.normal, plane.point, points[k], rays[k], kClaimDepth)) {
          members.push_back(k);
        }
      }
      if (members.size() < 3) break;
      plane = Refit(points, members);
    }
    std::vector<size_t> rest;
    for (size_t k : left) {
      plane.num_inliers += OnPlane(plane.normal, plane.point, points[k], rays[k]) ? 1 : 0;
      if (!OnPlane(plane.normal, plane.point, points[k], rays[k], kClaimDepth)) rest.push_back(k);
    }
    plane.num_claimed = static_cast<int>(left.size() - rest.size());
    if (static_cast<size_t>(plane.num_inliers) < needed) break;
    planes.push_back(plane);
    left.swap(rest);
  }
  return planes;
}

ConsensusPlanesReport OfferConsensusPlanes(const core::PassParams& params,
                                           const std::vector<int32_t>& labels,
                                           const std::vector<uint8_t>& evidence,
                                           const ConsensusOffer& offer, int num_threads) {
  ConsensusPlanesReport report;
  const core::PixelStateView& s = params.state;
  const int n = s.width * s.height;
  if (labels.size() != static_cast<size_t>(n) || evidence.size() != static_cast<size_t>(n)) {
    throw std::logic_error("consensus planes: labels, evidence and pixel state differ in size");
  }
  const int num_regions = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end());
  const auto ray = [&](int i) {
    return core::ViewRay(params.ref_camera, static_cast<float>(i % s.width),
                         static_cast<float>(i / s.width));
  };
  // The confirmed pixels of every region, and its planes.
  std::vector<std::vector<int>> members(num_regions + 1);
  for (int i = 0; i < n; ++i) {
    if (labels[i] > 0 && evidence[i] && s.depth[i] > 0.0f) members[labels[i]].push_back(i);
  }
  const int min_inliers = std::max(kMinInliersFloor, n / kPixelsPerInlier);
  std::vector<std::vector<ConsensusPlane>> planes(num_regions + 1);
  ParallelFor(1, num_regions + 1, num_threads, [&](int id) {
    if (static_cast<int>(members[id].size()) < min_inliers) return;
    std::vector<core::Vec3> points, rays;
    for (int i : members[id]) {
      rays.push_back(ray(i));
      points.push_back(s.depth[i] * rays.back());
    }
    const uint64_t key = core::RngKey(params.seed, params.image_id, params.pass_id, 0xC0DEu,
                                      static_cast<uint32_t>(id));
    planes[id] = FitConsensusPlanes(points, rays, min_inliers, key);
  });
  for (const auto& p : planes) report.num_planes += static_cast<int>(p.size());
  // The offer of every region: `offer`, or kSegmentOffer where `offer` asks
  // for one surface and the region's confirmed pixels are not on one plane.
  std::vector<const ConsensusOffer*> rule(num_regions + 1, &offer);
  for (int id = 1; offer.one_surface && id <= num_regions; ++id) {
    const bool one_surface = planes[id].size() == 1 &&
                             planes[id][0].num_claimed >= kOneSurfaceShare * members[id].size();
    if (!one_surface) rule[id] = &kSegmentOffer;
  }

  std::vector<int> offered(s.height, 0), taken(s.height, 0);
  ParallelFor(0, s.height, num_threads, [&](int row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      const float depth = s.depth[i];
      if (labels[i] <= 0 || planes[labels[i]].empty() || !(depth > 0.0f) ||
          core::IsUnlit(params, i) || !core::IsWeaklyTextured(params, col, row)) {
        continue;
      }
      const core::Vec3 r = ray(i);
      const ConsensusPlane* nearest = nullptr;
      const ConsensusOffer& region_offer = *rule[labels[i]];
      float nearest_error = region_offer.max_depth;
      for (const ConsensusPlane& plane : planes[labels[i]]) {
        const float on_plane = DepthOnRay(plane.normal, plane.point, r);
        const float error = std::fabs(on_plane - depth) / depth;
        if (on_plane > 0.0f && error < nearest_error) {
          nearest_error = error;
          nearest = &plane;
        }
      }
      if (nearest == nullptr) continue;
      ++offered[row];
      taken[row] +=
          OfferPlane(params, col, row, nearest->normal, nearest->point, region_offer.margin);
    }
  });
  for (int row = 0; row < s.height; ++row) {
    report.num_offered += offered[row];
    report.num_taken += taken[row];
  }
  return report;
}

}  // namespace msp
