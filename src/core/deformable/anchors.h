// Anchor search of the APD-MVS baseline (docs/method.md section 3.2): from an unreliable
// pixel p, rays in 8 sectors of 45 degrees (or the sectors of adaptive
// equidistribution, section 5) look for reliable pixels at radii 2, 4, 8, 16,
// 32, then every 25 px; a non-reliable hit snaps to its nearest
// reliable pixel. A RANSAC plane through the hits' 3D points (triangles that
// contain p) rejects hits on other surfaces; the inliers closest to it are the
// anchors whose windows form p's deformable patch (paper eq. 3).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/deformable/anchor_maps.h"
#include "core/deformable/deformable_limits.h"
#include "core/deformable/equidistribution.h"
#include "core/deformable/sectors.h"
#include "core/math/camera.h"
#include "core/math/hd.h"
#include "core/math/plane.h"
#include "core/math/rng.h"
#include "core/math/vec.h"

namespace msp {
namespace core {

// Ray radii: doubling from 2 px up to 32 px, then steps of 25 px.
constexpr int kFirstRayRadius = 2;
constexpr int kLastDoublingRadius = 32;
constexpr int kRayRadiusStep = 25;
// APD: 50 RANSAC tries, inlier threshold (0.01 - 0.00125 r) * depth range for
// round r (tighter on finer rounds), at least 6 inliers, 4 sectors with a hit.
constexpr int kDefaultRansacIterations = 50;
constexpr float kInlierFactorStart = 0.01f;
constexpr float kInlierFactorPerRound = 0.00125f;
constexpr float kMinInlierFactor = 0.00125f;  // floor for very deep pyramids
constexpr int kDefaultMinInliers = 6;
constexpr int kDefaultMinSectors = 4;
// Two rays per sector at the coarsest round, doubling to kMaxRaysPerSector.
constexpr int kCoarsestRaysPerSector = 2;
// Sample triangles thinner than this (sine of their angle) span no plane.
constexpr float kMinTriangleSine = 1e-3f;

struct AnchorParams {
  int rays_per_sector;     // 1..kMaxRaysPerSector
  int max_distance;        // px; rays stop here, snapped hits farther are dropped
  float inlier_threshold;  // point-to-plane distance of a RANSAC inlier (scene units)
  int min_inliers;
  int min_sectors;  // fewer sectors with a hit -> no anchors
  int ransac_iterations;
  // Adaptive equidistribution (equidistribution.h): re-cut the sectors per
  // pixel before the rays are cast; false = the fixed 45-degree sectors.
  bool equidistribution = false;
  int equidistribution_iterations = kDefaultEquidistributionIterations;  // 1..3
  // Inliers kept as anchors, closest to the plane first: kMaxAnchors (APD),
  // or every inlier (kMaxKeptAnchors) for disassemble-clustering.
  int max_anchors = kMaxAnchors;
};

// The anchors of one pixel and the RANSAC plane n^T X + plane_dist = 0
// (reference camera frame, n unit and facing the camera at p).
// The anchors are sorted by distance to the plane, so the first kMaxAnchors
// are APD's anchors whatever AnchorParams::max_anchors kept.
struct AnchorSet {
  int count;  // 0 when the search failed (the pixel is then matched conventionally)
  int cols[kMaxKeptAnchors];
  int rows[kMaxKeptAnchors];
  Vec3 plane_normal;
  float plane_dist;
  int num_sectors;  // sectors with at least one hit
  int num_inliers;
};

MSP_HD float AnchorInlierThreshold(int round, float depth_range) {
  const float factor = kInlierFactorStart - kInlierFactorPerRound * static_cast<float>(round);
  return fmaxf(factor, kMinInlierFactor) * depth_range;
}

MSP_HD int RaysPerSector(int round) {
  int rays = kCoarsestRaysPerSector;
  for (int r = 0; r < round && rays < kMaxRaysPerSector; ++r) rays *= 2;
  return rays < kMaxRaysPerSector ? rays : kMaxRaysPerSector;
}

MSP_HD AnchorParams DefaultAnchorParams(int round, float depth_range, int max_distance) {
  return AnchorParams{
      RaysPerSector(round), max_distance,       AnchorInlierThreshold(round, depth_range),
      kDefaultMinInliers,   kDefaultMinSectors, kDefaultRansacIterations};
}

MSP_HD int NextRayRadius(int radius) {
  return radius < kLastDoublingRadius ? 2 * radius : radius + kRayRadiusStep;
}

// True when (x, y) lies inside or on the triangle (a, b, c) (image space).
MSP_HD bool TriangleContains(float ax, float ay, float bx, float by, float cx, float cy, float x,
                             float y) {
  const float d1 = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
  const float d2 = (cx - bx) * (y - by) - (cy - by) * (x - bx);
  const float d3 = (ax - cx) * (y - cy) - (ay - cy) * (x - cx);
  // Bitwise, not short-circuit: the signs are unpredictable, branches cost more.
  const bool has_neg = (d1 < 0.0f) | (d2 < 0.0f) | (d3 < 0.0f);
  const bool has_pos = (d1 > 0.0f) | (d2 > 0.0f) | (d3 > 0.0f);
  return !(has_neg & has_pos);
}

MSP_HD bool Contains(const int* values, int n, int v) {
  for (int k = 0; k < n; ++k) {
    if (values[k] == v) return true;
  }
  return false;
}

// The reliable pixel hit by the ray `ray` of the sector whose centre line is
// `sector`, or -1; a snapped hit must lie within acos(min_cos) of that line
// (inside the sector's span). A hit already taken by another ray (neighbouring
// rays often snap to the same pixel) does not stop the ray: it walks on to
// find a distinct one. When confined, the ray ends at the first ray position behind
// a depth edge (every farther one is behind it too), and a snapped hit behind
// an edge is skipped. The ray is walked once, position to position, rather
// than from p again for every position.
MSP_HD int CastAnchorRay(const AnchorMaps& maps, int col, int row, RayDirection sector,
                         float min_cos, RayDirection ray, int max_distance, const int* taken,
                         int num_taken) {
  int walked_col = col, walked_row = row;  // the ray is clear of edges up to here
  // The last snapped hit found behind an edge: consecutive radii often repeat it.
  int crossing = -1;
  for (int radius = kFirstRayRadius; radius <= max_distance; radius = NextRayRadius(radius)) {
    const int c = static_cast<int>(floorf(col + ray.x * radius + 0.5f));
    const int r = static_cast<int>(floorf(row + ray.y * radius + 0.5f));
    if (c < 0 || r < 0 || c >= maps.width || r >= maps.height) return -1;
    int q = r * maps.width + c;
    if (IsConfined(maps) && WalkCrossesEdge(maps, walked_col, walked_row, c, r)) {
      return -1;
    }
    walked_col = c;
    walked_row = r;
    const bool snapped = maps.classes[q] != kReliable;
    if (snapped) {
      q = maps.nearest[q];
      if (q < 0 || q == crossing) continue;
      const float ox = static_cast<float>(q % maps.width - col);
      const float oy = static_cast<float>(q / maps.width - row);
      const float len2 = ox * ox + oy * oy;
      if (len2 > static_cast<float>(max_distance) * max_distance || len2 <= 0.0f) continue;
      if (ox * sector.x + oy * sector.y < min_cos * sqrtf(len2)) continue;  // left the sector
    }
    if (!(maps.depth[q] > 0.0f) || Contains(taken, num_taken, q)) continue;
    // The walk to a snapped hit is the costly test: last, and once per hit.
    if (snapped && CrossesDepthEdge(maps, col, row, q)) {
      crossing = q;
      continue;
    }
    return q;
  }
  return -1;
}

// Ray hits of all sectors, all distinct: the fixed sectors, or those of
// adaptive equidistribution. Returns the number of hits; *num_sectors
// receives the number of sectors with at least one.
MSP_HD int CollectAnchorHits(const AnchorMaps& maps, int col, int row, const AnchorParams& params,
                             int* hits, int* num_sectors) {
  SectorRays sectors;
  if (params.equidistribution) {
    EquidistributedSectorRays(maps, col, row, params.max_distance,
                              params.equidistribution_iterations, RecutWhere::kSomeSectorClosed,
                              params.rays_per_sector, &sectors);
  } else {
    FixedSectorRays(params.rays_per_sector, &sectors);
  }
  const int rays = sectors.rays;
  int n = 0;
  *num_sectors = 0;
  for (int sector = 0; sector < kNumSectors; ++sector) {
    bool any = false;
    for (int k = 0; k < rays; ++k) {
      const int q = CastAnchorRay(maps, col, row, sectors.centre[sector], sectors.min_cos[sector],
                                  sectors.ray[sector * rays + k], params.max_distance, hits, n);
      if (q < 0) continue;
      any = true;
      hits[n++] = q;
    }
    if (any) ++*num_sectors;
  }
  return n;
}

MSP_HD int DrawIndex(Rng* rng, int n) {
  const int k = static_cast<int>(rng->Uniform() * static_cast<float>(n));
  return k < n ? k : n - 1;
}

// The ray hits of one pixel. Within a pass they stay the same (the classes,
// the nearest-reliable map and the edges are fixed, and a depth once positive
// stays so), so they are cast once per pass and refitted every iteration.
struct AnchorHits {
  int count;
  int num_sectors;
  int index[kMaxAnchorHits];
};

MSP_HD void CastAnchorHits(const AnchorMaps& maps, int col, int row, const AnchorParams& params,
                           AnchorHits* hits) {
  hits->count = CollectAnchorHits(maps, col, row, params, hits->index, &hits->num_sectors);
}

// True while every hit still has a depth on maps (else they must be cast again).
MSP_HD bool HitsStillValid(const AnchorMaps& maps, const AnchorHits& hits) {
  for (int k = 0; k < hits.count; ++k) {
    if (!(maps.depth[hits.index[k]] > 0.0f)) return false;
  }
  return true;
}

// The RANSAC step of the anchor search on the hits' current depths. Returns
// false (and out->count = 0) with fewer than params.min_sectors sectors hit,
// or when no plane through a triangle containing p has params.min_inliers inliers.
MSP_HD bool FitAnchors(const Camera& cam, const AnchorMaps& maps, int col, int row,
                       const AnchorParams& params, const AnchorHits& cast, Rng* rng,
                       AnchorSet* out) {
  out->count = 0;
  out->num_inliers = 0;
  out->num_sectors = cast.num_sectors;
  const int n = cast.count;
  const int* hits = cast.index;
  if (out->num_sectors < params.min_sectors || n < 3) return false;
  Vec3 points[kMaxAnchorHits];
  float hit_x[kMaxAnchorHits], hit_y[kMaxAnchorHits];  // image positions, for the triangle test
  for (int k = 0; k < n; ++k) {
    hit_x[k] = static_cast<float>(hits[k] % maps.width);
    hit_y[k] = static_cast<float>(hits[k] / maps.width);
    points[k] = BackProject(cam, hit_x[k], hit_y[k], maps.depth[hits[k]]);
  }
  const float px = static_cast<float>(col), py = static_cast<float>(row);
  int best_count = 0;
  float best_residual = 0.0f;
  Vec3 best_normal{0.0f, 0.0f, 0.0f};
  float best_dist = 0.0f;
  for (int it = 0; it < params.ransac_iterations; ++it) {
    const int a = DrawIndex(rng, n), b = DrawIndex(rng, n), c = DrawIndex(rng, n);
    if (a == b || b == c || a == c) continue;
    if (!TriangleContains(hit_x[a], hit_y[a], hit_x[b], hit_y[b], hit_x[c], hit_y[c], px, py)) {
      continue;
    }
    const Vec3 u = points[b] - points[a], v = points[c] - points[a];
    const Vec3 normal = Cross(u, v);
    const float area2 = Dot(normal, normal);
    if (!(area2 > kMinTriangleSine * kMinTriangleSine * Dot(u, u) * Dot(v, v))) continue;
    const Vec3 unit = (1.0f / sqrtf(area2)) * normal;
    const float dist = -Dot(unit, points[a]);
    int count = 0;
    float residual = 0.0f;
    for (int k = 0; k < n; ++k) {  // branch-free: inliers are unpredictable
      const float e = fabsf(Dot(unit, points[k]) + dist);
      const bool inlier = e <= params.inlier_threshold;
      count += inlier;
      residual += inlier ? e : 0.0f;
    }
    if (count > best_count || (count == best_count && residual < best_residual)) {
      best_count = count;
      best_residual = residual;
      best_normal = unit;
      best_dist = dist;
    }
  }
  out->num_inliers = best_count;
  if (best_count < params.min_inliers) return false;
  // Face the camera at p: n . ray < 0 (then plane_dist > 0 for a plane in front).
  if (Dot(best_normal, ViewRay(cam, px, py)) > 0.0f) {
    best_normal = -best_normal;
    best_dist = -best_dist;
  }
  out->plane_normal = best_normal;
  out->plane_dist = best_dist;
  // The inliers closest to the plane become the anchors (selection by
  // distance), up to params.max_anchors of them.
  constexpr float kNotAnInlier = 1e30f;  // outliers, and inliers already taken
  float error[kMaxAnchorHits];
  for (int k = 0; k < n; ++k) {
    const float e = fabsf(Dot(best_normal, points[k]) + best_dist);
    error[k] = e <= params.inlier_threshold ? e : kNotAnInlier;
  }
  const int max_anchors =
      params.max_anchors < kMaxKeptAnchors ? params.max_anchors : kMaxKeptAnchors;
  while (out->count < max_anchors) {
    int pick = 0;  // the first smallest error, branch-free
    for (int k = 1; k < n; ++k) {
      const bool smaller = error[k] < error[pick];
      pick = smaller ? k : pick;
    }
    if (!(error[pick] < kNotAnInlier)) break;
    out->cols[out->count] = hits[pick] % maps.width;
    out->rows[out->count] = hits[pick] / maps.width;
    ++out->count;
    error[pick] = kNotAnInlier;
  }
  return true;
}

// p's hypothesis on the anchors' RANSAC plane (depth 0 when the ray misses it).
MSP_HD PlaneHypothesis AnchorPlaneHypothesis(const Camera& cam, const AnchorSet& anchors, int col,
                                             int row) {
  return PlaneHypothesis{DepthOnPlane(cam, anchors.plane_normal, anchors.plane_dist,
                                      static_cast<float>(col), static_cast<float>(row)),
                         anchors.plane_normal};
}

}  // namespace core
}  // namespace msp
