// Adaptive equidistribution (paper eq. 7, docs/method.md section 5): edge
// confinement can leave a fixed 45-degree sector of an unreliable pixel p
// without anchors, walled off by depth edges, while the reliable pixels lie
// elsewhere. The sectors are re-cut so that each faces about the same number
// of reliable pixels; the anchor search then runs per new sector.
//
// Rays from p stop at their boundary pixel b_i, the first reliable pixel or
// depth edge. The sector between two consecutive rays counts n_i = |b_i -
// b_{i+1}|_1 reliable pixels (they lie continuously along the front between
// the two), or none when either ray ends on an edge, at the image border or
// nowhere within reach. The new boundaries are where the cumulative count
// reaches k d_bar (d_bar the mean over the 8 sectors).
#pragma once

#include <cmath>

#include "core/deformable/anchor_maps.h"
#include "core/deformable/deformable_limits.h"
#include "core/deformable/sectors.h"
#include "core/math/hd.h"
#include "core/prior/segment_crossing.h"

namespace msp {
namespace core {

constexpr int kMaxEquidistributionIterations = 3;
constexpr int kDefaultEquidistributionIterations = 2;
// Every iteration casts at most 8 new boundary rays; all of them are kept.
constexpr int kMaxBoundaryRays = kNumSectors * kMaxEquidistributionIterations;
// The first boundary rays lie on the fixed sectors' boundaries (22.5 + 45 k
// degrees): a pixel without any count keeps exactly the fixed sectors.
constexpr float kFirstBoundaryDegrees = -0.5f * kSectorDegrees;
// A new boundary ray this close to an earlier one is that ray.
constexpr float kSameRayDegrees = 1e-3f;

// The boundary pixel b of the ray at `degrees`.
struct BoundaryPixel {
  float degrees;  // in [kFirstBoundaryDegrees, kFirstBoundaryDegrees + 360)
  int col, row;   // meaningful when reliable
  bool reliable;  // false: a depth edge, the image border or nothing within reach
};

// n_i of the sector between boundary pixels a and b.
MSP_HD float SectorReliableCount(const BoundaryPixel& a, const BoundaryPixel& b) {
  if (!a.reliable || !b.reliable) return 0.0f;
  const int dc = a.col > b.col ? a.col - b.col : b.col - a.col;
  const int dr = a.row > b.row ? a.row - b.row : b.row - a.row;
  return static_cast<float>(dc + dr);
}

// Eq. 7 as an inverse of the cumulative count. Sector i of n spans
// [start[i], start[i + 1]] (start[n] = start[0] + 360, starts increasing)
// and holds counts[i] >= 0, in all total > 0. boundaries[k] is the angle
// where the cumulative count reaches k d_bar, d_bar = total / 8: inside the
// sector x with sum_{i<x} d_i <= k d_bar < sum_{i<=x} d_i, linearly over x's
// span. The paper's eq. 7 divides by d_x alone, which leaves out the unit of
// the angle; the fraction of d_x is taken as that fraction of x's span. A
// sector without count never holds a boundary inside it: its span joins the
// new sector before it.
MSP_HD void EquidistributeAngles(const float* start, const float* counts, int n, float total,
                                 float* boundaries) {
  int x = 0;
  float before = 0.0f;  // sum_{i<x} d_i
  for (int k = 0; k < kNumSectors; ++k) {
    const float value = static_cast<float>(k) * total / static_cast<float>(kNumSectors);
    while (x < n - 1 && !(value < before + counts[x])) before += counts[x++];
    const float end = x + 1 < n ? start[x + 1] : start[0] + 360.0f;
    float t = counts[x] > 0.0f ? (value - before) / counts[x] : 0.0f;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    boundaries[k] = start[x] + t * (end - start[x]);
  }
}

// The boundary pixel of the ray from p at `degrees`: the first pixel of the
// Bresenham walk towards max_distance that is an edge (when confined; p
// itself is not tested, as in the crossing test) or reliable.
MSP_HD BoundaryPixel CastBoundaryRay(const AnchorMaps& maps, int col, int row, float degrees,
                                     int max_distance) {
  BoundaryPixel b{degrees, col, row, false};
  const RayDirection d = DirectionAt(degrees);
  const int end_col = static_cast<int>(floorf(col + d.x * max_distance + 0.5f));
  const int end_row = static_cast<int>(floorf(row + d.y * max_distance + 0.5f));
  const bool confined = IsConfined(maps);
  for (LineWalk walk(col, row, end_col, end_row); !walk.Done();) {
    walk.Next();
    if (walk.col < 0 || walk.row < 0 || walk.col >= maps.width || walk.row >= maps.height) break;
    if (confined && maps.edges.At(walk.col, walk.row)) break;
    if (maps.classes[walk.row * maps.width + walk.col] == kReliable) {
      b.col = walk.col;
      b.row = walk.row;
      b.reliable = true;
      break;
    }
  }
  return b;
}

// Inserts b into rays[0..*n), kept in increasing angle, unless a ray at its
// angle is there already.
MSP_HD void InsertBoundaryRay(const BoundaryPixel& b, BoundaryPixel* rays, int* n) {
  int at = *n;
  while (at > 0 && rays[at - 1].degrees > b.degrees) --at;
  if ((at > 0 && b.degrees - rays[at - 1].degrees < kSameRayDegrees) ||
      (at < *n && rays[at].degrees - b.degrees < kSameRayDegrees)) {
    return;
  }
  for (int k = *n; k > at; --k) rays[k] = rays[k - 1];
  rays[at] = b;
  ++*n;
}

// True when a ray at `degrees` is among rays[0..n).
MSP_HD bool HasBoundaryRay(const BoundaryPixel* rays, int n, float degrees) {
  for (int k = 0; k < n; ++k) {
    if (fabsf(rays[k].degrees - degrees) < kSameRayDegrees) return true;
  }
  return false;
}

// The reliable count around p as the boundary rays estimate it: sector i of
// n spans [start[i], start[i + 1]] (start[n] = start[0] + 360) and counts
// counts[i], in all total.
struct CumulativeCount {
  int n;
  float start[kMaxBoundaryRays];
  float counts[kMaxBoundaryRays];
  float total;
};

// The cumulative count of the boundary rays rays[0..n), sorted by angle.
MSP_HD void CountBetweenRays(const BoundaryPixel* rays, int n, CumulativeCount* out) {
  out->n = n;
  out->total = 0.0f;
  for (int i = 0; i < n; ++i) {
    out->start[i] = rays[i].degrees;
    out->counts[i] = SectorReliableCount(rays[i], rays[i + 1 < n ? i + 1 : 0]);
    out->total += out->counts[i];
  }
}

// Which pixels get re-cut sectors. Re-cutting where every fixed sector
// already reaches reliable pixels equalises counts but moves the anchors off
// the directions that enclose p: on the bundled scene (320x240, 6 views, 3
// seeds) it cost 0.10 of fused accuracy at 2 % against fixed sectors, while
// re-cutting only where a depth edge or the border closes a sector (the case
// eq. 7 is for) is level with them.
enum class RecutWhere { kEverywhere, kSomeSectorClosed };

// True when every sector counts reliable pixels: no sector is closed.
MSP_HD bool AllSectorsOpen(const CumulativeCount& count) {
  for (int i = 0; i < count.n; ++i) {
    if (!(count.counts[i] > 0.0f)) return false;
  }
  return true;
}

// The 8 sector boundaries of p after `iterations` re-cuts (eq. 7), in
// increasing angle within [boundaries[0], boundaries[0] + 360), and the
// cumulative count of the last re-cut; with kSomeSectorClosed, only when a
// fixed sector counts nothing. Each iteration casts boundary rays at
// the current boundaries (the fixed sectors' boundaries first) and re-cuts
// from all boundary rays cast so far. (Re-estimating from the 8 newest rays
// alone, as a literal reading has it, forgets what the earlier rays found: a
// new sector whose two ends are reliable but which spans a range found closed
// counts as full again, and the re-cuts swing back and forth.) Returns false,
// with the fixed sectors' boundaries, when no re-cut took place.
MSP_HD bool EquidistributedBoundaries(const AnchorMaps& maps, int col, int row, int max_distance,
                                      int iterations, RecutWhere recut_where, float* boundaries,
                                      CumulativeCount* cumulative) {
  if (iterations > kMaxEquidistributionIterations) iterations = kMaxEquidistributionIterations;
  BoundaryPixel cast[kMaxBoundaryRays];
  int n = 0;
  for (int k = 0; k < kNumSectors; ++k) boundaries[k] = kFirstBoundaryDegrees + kSectorDegrees * k;
  bool recut = false;
  for (int it = 0; it < iterations; ++it) {
    for (int k = 0; k < kNumSectors; ++k) {
      if (HasBoundaryRay(cast, n, boundaries[k])) continue;
      InsertBoundaryRay(CastBoundaryRay(maps, col, row, boundaries[k], max_distance), cast, &n);
    }
    CumulativeCount count;
    CountBetweenRays(cast, n, &count);
    if (!(count.total > 0.0f)) break;  // keeps the last boundaries
    if (it == 0 && recut_where == RecutWhere::kSomeSectorClosed && AllSectorsOpen(count)) break;
    *cumulative = count;
    EquidistributeAngles(count.start, count.counts, count.n, count.total, boundaries);
    recut = true;
  }
  return recut;
}

// The sectors of p's anchor search: those of EquidistributedBoundaries, each
// with its rays spread evenly in angle over its span, as in a fixed sector. A
// new sector's span may hold a range the boundary rays found closed; its rays
// still look there, since a closed boundary ray closes only its own
// direction. Returns false (and the fixed sectors) when no re-cut took place.
MSP_HD bool EquidistributedSectorRays(const AnchorMaps& maps, int col, int row, int max_distance,
                                      int iterations, RecutWhere recut_where, int rays_per_sector,
                                      SectorRays* out) {
  const int rays = ClampRaysPerSector(rays_per_sector);
  float boundaries[kNumSectors];
  CumulativeCount count;
  if (!EquidistributedBoundaries(maps, col, row, max_distance, iterations, recut_where,
                                 boundaries, &count)) {
    FixedSectorRays(rays, out);
    return false;
  }
  out->rays = rays;
  for (int k = 0; k < kNumSectors; ++k) {
    const float start = boundaries[k];
    const float span = (k + 1 < kNumSectors ? boundaries[k + 1] : boundaries[0] + 360.0f) - start;
    out->centre[k] = DirectionAt(start + 0.5f * span);
    out->min_cos[k] = cosf(0.5f * span * kDegToRad);
    for (int j = 0; j < rays; ++j) {
      out->ray[k * rays + j] = DirectionAt(start + (j + 0.5f) / rays * span);
    }
  }
  return true;
}

}  // namespace core
}  // namespace msp
