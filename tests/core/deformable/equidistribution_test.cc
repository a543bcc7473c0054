#include "core/deformable/equidistribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <vector>

#include "base/nearest_marked_pixels.h"
#include "core/deformable/anchors.h"
#include "tests/support/cameras.h"
#include "tests/support/images.h"

namespace msp {
namespace core {
namespace {

constexpr int kSize = 120;
constexpr int kCol = 60, kRow = 60;  // the unreliable pixel p
constexpr float kDepthRange = 10.0f;
constexpr int kMaxDistance = 100;
constexpr double kPi = 3.14159265358979;

// The whole anchor search for pixel (col, row), as the deformable sweeps run
// it: the rays, then the RANSAC fit.
bool FindAnchors(const Camera& cam, const AnchorMaps& maps, int col, int row,
                 const AnchorParams& params, Rng* rng, AnchorSet* out) {
  AnchorHits hits;
  CastAnchorHits(maps, col, row, params, &hits);
  return FitAnchors(cam, maps, col, row, params, hits, rng, out);
}

// Angle of the offset (dx, dy) from p in degrees, in [-180, 180].
double AngleOf(double dx, double dy) { return std::atan2(dy, dx) * 180.0 / kPi; }

// `degrees` moved by whole turns into [from, from + 360).
double Wrap(double degrees, double from) {
  while (degrees < from) degrees += 360.0;
  while (degrees >= from + 360.0) degrees -= 360.0;
  return degrees;
}

// Reliable pixels on a slanted plane, depth edges, and the maps the anchor
// search reads.
struct Layout {
  Camera cam = test::SkewedIntrinsicsCamera(kSize, kSize, 100.0f, test::Identity(), Vec3{0, 0, 0});
  Vec3 normal = Normalized(Vec3{0.2f, -0.1f, -1.0f});
  float dist = 5.0f;
  std::vector<uint8_t> classes = std::vector<uint8_t>(kSize * kSize, kUnreliable);
  std::vector<float> depth = std::vector<float>(kSize * kSize, 0.0f);
  std::vector<int> nearest;
  test::EdgeMap edges = test::NoEdges(kSize, kSize);

  float TrueDepth(float c, float r) const { return DepthOnPlane(cam, normal, dist, c, r); }

  // Pixels at offset (dx, dy) from p where `reliable` holds become reliable.
  void Fill(const std::function<bool(int, int)>& reliable) {
    for (int r = 0; r < kSize; ++r) {
      for (int c = 0; c < kSize; ++c) {
        if (!(c == kCol && r == kRow) && reliable(c - kCol, r - kRow)) {
          classes[r * kSize + c] = kReliable;
          depth[r * kSize + c] = TrueDepth(static_cast<float>(c), static_cast<float>(r));
        }
      }
    }
    nearest = NearestReliablePixels(classes.data(), kSize, kSize, 1);
  }

  // Pixels at offset (dx, dy) from p where `edge` holds become depth edges.
  void Edges(const std::function<bool(int, int)>& edge) {
    for (int r = 0; r < kSize; ++r) {
      for (int c = 0; c < kSize; ++c) {
        if (edge(c - kCol, r - kRow)) edges.bits[r * kSize + c] = 1;
      }
    }
  }

  AnchorMaps Maps() const {
    return AnchorMaps{classes.data(), nearest.data(), depth.data(), kSize, kSize, edges.View()};
  }
  AnchorMaps Unconfined() const {
    AnchorMaps maps = Maps();
    maps.edges = BoundaryView{nullptr, 0, 0, 0};
    return maps;
  }
};

// The fixed sectors' boundaries: -22.5 + 45 k degrees.
void FixedBoundaries(float* start) {
  for (int k = 0; k < kNumSectors; ++k) start[k] = kFirstBoundaryDegrees + kSectorDegrees * k;
}

// The cumulative count of eq. 7 at `degrees` in [start[0], start[0] + 360),
// computed directly: whole sectors before it, the covered fraction of its own.
double CumulativeAt(const float* start, const float* counts, int n, double degrees) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double end = i + 1 < n ? start[i + 1] : start[0] + 360.0;
    if (degrees >= end) {
      sum += counts[i];
    } else if (degrees > start[i]) {
      sum += counts[i] * (degrees - start[i]) / (end - start[i]);
    }
  }
  return sum;
}

TEST(Equidistribution, SectorCountIsTheL1DistanceBetweenReliableBoundaryPixels) {
  const BoundaryPixel a{0.0f, 10, 20, true}, b{45.0f, 13, 16, true};
  EXPECT_EQ(SectorReliableCount(a, b), 7.0f);
  EXPECT_EQ(SectorReliableCount(b, a), 7.0f);
  BoundaryPixel closed = b;
  closed.reliable = false;  // on a depth edge: the sector holds no reliable pixel
  EXPECT_EQ(SectorReliableCount(a, closed), 0.0f);
  EXPECT_EQ(SectorReliableCount(closed, a), 0.0f);
}

TEST(Equidistribution, EqualCountsKeepTheSectors) {
  float start[kNumSectors], out[kNumSectors];
  FixedBoundaries(start);
  const float counts[kNumSectors] = {5, 5, 5, 5, 5, 5, 5, 5};
  EquidistributeAngles(start, counts, kNumSectors, 40.0f, out);
  for (int k = 0; k < kNumSectors; ++k) EXPECT_NEAR(out[k], start[k], 1e-4f) << k;
}

TEST(Equidistribution, OneCountedSectorIsCutInEight) {
  float start[kNumSectors], out[kNumSectors];
  FixedBoundaries(start);
  const float counts[kNumSectors] = {8, 0, 0, 0, 0, 0, 0, 0};
  EquidistributeAngles(start, counts, kNumSectors, 8.0f, out);
  for (int k = 0; k < kNumSectors; ++k) EXPECT_NEAR(out[k], -22.5f + 5.625f * k, 1e-4f) << k;
}

// Counts [5, 1, 0, 3, 0, 0, 2, 5]: d_bar = 2, and each new sector holds 2.
TEST(Equidistribution, NewSectorsHoldEqualCumulativeCounts) {
  float start[kNumSectors], out[kNumSectors];
  FixedBoundaries(start);
  const float counts[kNumSectors] = {5, 1, 0, 3, 0, 0, 2, 5};
  EquidistributeAngles(start, counts, kNumSectors, 16.0f, out);
  for (int k = 0; k < kNumSectors; ++k) {
    EXPECT_NEAR(CumulativeAt(start, counts, kNumSectors, out[k]), 2.0 * k, 1e-4) << k;
    if (k > 0) {
      EXPECT_GT(out[k], out[k - 1]);
    }
    // No boundary inside a sector without count: it gets no sector of its own.
    for (int i : {2, 4, 5}) {
      EXPECT_FALSE(out[k] > start[i] && out[k] < start[i + 1]) << k << " in sector " << i;
    }
  }
  // Inside old sector 0 (5 px over 45 degrees) the boundaries move 18 degrees
  // per d_bar: the interpolation runs over the old sector's span.
  EXPECT_NEAR(out[1], -22.5f + 18.0f, 1e-4f);
  EXPECT_NEAR(out[2], -22.5f + 36.0f, 1e-4f);
  // The cumulative count reaches 6 at the end of sector 1; the empty sector 2
  // joins new sector 2, and new sector 3 starts where sector 3 does.
  EXPECT_NEAR(out[3], start[3], 1e-4f);
}

TEST(Equidistribution, BoundaryRayStopsAtTheFirstReliablePixelOrEdge) {
  Layout layout;
  layout.Fill([](int dx, int) { return dx >= 10; });  // reliable from 10 px east
  BoundaryPixel b = CastBoundaryRay(layout.Maps(), kCol, kRow, 0.0f, kMaxDistance);
  EXPECT_TRUE(b.reliable);
  EXPECT_EQ(b.col, kCol + 10);
  EXPECT_EQ(b.row, kRow);
  EXPECT_EQ(b.degrees, 0.0f);
  // 45 degrees: the diagonal reaches the reliable half-plane at (10, 10).
  b = CastBoundaryRay(layout.Maps(), kCol, kRow, 45.0f, kMaxDistance);
  EXPECT_TRUE(b.reliable);
  EXPECT_EQ(b.col - kCol, 10);
  EXPECT_EQ(b.row - kRow, 10);
  // Westwards nothing within reach before the image border.
  EXPECT_FALSE(CastBoundaryRay(layout.Maps(), kCol, kRow, 180.0f, kMaxDistance).reliable);
  // Out of reach.
  EXPECT_FALSE(CastBoundaryRay(layout.Maps(), kCol, kRow, 0.0f, 9).reliable);
  EXPECT_TRUE(CastBoundaryRay(layout.Maps(), kCol, kRow, 0.0f, 10).reliable);
  // A depth edge 5 px east stops the ray when confined, not when unconfined.
  layout.edges = test::VerticalEdge(kSize, kSize, kCol + 5);
  EXPECT_FALSE(CastBoundaryRay(layout.Maps(), kCol, kRow, 0.0f, kMaxDistance).reliable);
  b = CastBoundaryRay(layout.Unconfined(), kCol, kRow, 0.0f, kMaxDistance);
  EXPECT_TRUE(b.reliable);
  EXPECT_EQ(b.col, kCol + 10);
  // p itself on an edge does not stop the ray (as in the crossing test).
  layout.edges = test::VerticalEdge(kSize, kSize, kCol - 1);
  EXPECT_TRUE(CastBoundaryRay(layout.Maps(), kCol, kRow, 0.0f, kMaxDistance).reliable);
}

TEST(Equidistribution, BoundaryRaysKeptSortedWithoutRepeats) {
  BoundaryPixel rays[kMaxBoundaryRays];
  int n = 0;
  for (float degrees : {40.0f, -22.5f, 100.0f, 40.0f, 70.0f, -22.5f}) {
    InsertBoundaryRay(BoundaryPixel{degrees, 0, 0, false}, rays, &n);
  }
  ASSERT_EQ(n, 4);
  EXPECT_EQ(rays[0].degrees, -22.5f);
  EXPECT_EQ(rays[1].degrees, 40.0f);
  EXPECT_EQ(rays[2].degrees, 70.0f);
  EXPECT_EQ(rays[3].degrees, 100.0f);
  EXPECT_TRUE(HasBoundaryRay(rays, n, 70.0f));
  EXPECT_FALSE(HasBoundaryRay(rays, n, 71.0f));
}

// The count a new sector really faces: the L1 length of the reliable front
// (the boundary pixels) over its span, from a fan of rays every 0.05
// degrees; only the angles inside `counted` (a predicate on degrees) count.
std::vector<double> FrontCounts(const AnchorMaps& maps, const float* boundaries,
                                const std::function<bool(double)>& counted) {
  std::vector<double> counts(kNumSectors, 0.0);
  constexpr double kStep = 0.05;
  for (int k = 0; k < kNumSectors; ++k) {
    const double end = k + 1 < kNumSectors ? boundaries[k + 1] : boundaries[0] + 360.0;
    BoundaryPixel previous = CastBoundaryRay(maps, kCol, kRow, boundaries[k], kMaxDistance);
    for (double a = boundaries[k] + kStep; a <= end + 1e-9; a += kStep) {
      const double at = std::min(a, end);
      const BoundaryPixel b =
          CastBoundaryRay(maps, kCol, kRow, static_cast<float>(at), kMaxDistance);
      if (counted(Wrap(at - 0.5 * kStep, -180.0))) counts[k] += SectorReliableCount(previous, b);
      previous = b;
    }
  }
  return counts;
}

// Largest relative deviation of the counts from their mean.
double Spread(const std::vector<double>& counts) {
  double mean = 0.0;
  for (double c : counts) mean += c / counts.size();
  double worst = 0.0;
  for (double c : counts) worst = std::max(worst, std::fabs(c - mean) / mean);
  return worst;
}

// Reliable pixels outside a circle of radius 30 whose centre lies 15 px east
// of p: the front is 15 px from p to the west, 45 px to the east, and
// longer in L1 on the east. The fixed sectors face very different counts;
// after the re-cuts they face nearly equal ones.
TEST(Equidistribution, IteratedSectorsFaceEqualCounts) {
  Layout layout;
  layout.Fill([](int dx, int dy) { return (dx - 15) * (dx - 15) + dy * dy > 30 * 30; });
  const AnchorMaps maps = layout.Maps();
  const auto everywhere = [](double) { return true; };
  float fixed[kNumSectors];
  FixedBoundaries(fixed);
  const double fixed_spread = Spread(FrontCounts(maps, fixed, everywhere));
  double spread[kMaxEquidistributionIterations + 1];
  for (int iterations = 1; iterations <= kMaxEquidistributionIterations; ++iterations) {
    float boundaries[kNumSectors];
    CumulativeCount count;
    ASSERT_TRUE(EquidistributedBoundaries(maps, kCol, kRow, kMaxDistance, iterations,
                                          RecutWhere::kEverywhere, boundaries, &count));
    spread[iterations] = Spread(FrontCounts(maps, boundaries, everywhere));
  }
  // Measured: fixed 0.55; 0.23, 0.13, 0.10 after 1, 2, 3 re-cuts (a sector
  // faces about 30 px of front: a few pixels of rounding are 10 %).
  EXPECT_GT(fixed_spread, 0.4);
  EXPECT_LT(spread[1], 0.5 * fixed_spread);
  EXPECT_LT(spread[2], 0.15);  // every new sector within 15 % of the mean
  EXPECT_LT(spread[3], 0.12);
  EXPECT_LT(spread[3], spread[2]);
  EXPECT_LT(spread[2], spread[1]);
}

// Where every fixed sector reaches reliable pixels, only kEverywhere re-cuts:
// the layout of IteratedSectorsFaceEqualCounts keeps the fixed sectors with
// kSomeSectorClosed.
TEST(Equidistribution, OpenSectorsKeptWhereNoneIsClosed) {
  Layout layout;
  layout.Fill([](int dx, int dy) { return (dx - 15) * (dx - 15) + dy * dy > 30 * 30; });
  SectorRays fixed, rays;
  std::memset(&fixed, 0, sizeof(fixed));
  std::memset(&rays, 0, sizeof(rays));
  FixedSectorRays(2, &fixed);
  EXPECT_FALSE(EquidistributedSectorRays(layout.Maps(), kCol, kRow, kMaxDistance, 2,
                                         RecutWhere::kSomeSectorClosed, 2, &rays));
  EXPECT_EQ(std::memcmp(&rays, &fixed, sizeof(SectorRays)), 0);
  EXPECT_TRUE(EquidistributedSectorRays(layout.Maps(), kCol, kRow, kMaxDistance, 2,
                                        RecutWhere::kEverywhere, 2, &rays));
  EXPECT_NE(std::memcmp(&rays, &fixed, sizeof(SectorRays)), 0);
}

// Reliable pixels outside a circle of radius 25 around p, and a depth edge
// 13 px west of p: the boundary rays at 157.5 and 202.5 degrees end on the
// edge, those at 112.5 and 247.5 on reliable pixels. The three sectors
// between them count nothing and get no boundary of their own, and the
// counted range [-112.5, 112.5] is cut in equal counts. (The front the edge
// leaves visible just inside those sectors, up to 121 degrees, stays
// uncounted: the estimate sees only the boundary rays.)
TEST(Equidistribution, SectorsClosedByAnEdgeGetNoWidth) {
  Layout layout;
  layout.Fill([](int dx, int dy) { return dx * dx + dy * dy > 25 * 25; });
  layout.edges = test::VerticalEdge(kSize, kSize, kCol - 14);
  const AnchorMaps maps = layout.Maps();
  float boundaries[kNumSectors];
  CumulativeCount count;
  ASSERT_TRUE(EquidistributedBoundaries(maps, kCol, kRow, kMaxDistance,
                                        kDefaultEquidistributionIterations,
                                        RecutWhere::kSomeSectorClosed, boundaries, &count));
  const auto in_counted_range = [](double degrees) { return std::fabs(degrees) < 112.5; };
  for (int k = 0; k < kNumSectors; ++k) {
    EXPECT_TRUE(std::fabs(Wrap(boundaries[k], -180.0)) <= 112.5 + 1e-3) << boundaries[k];
  }
  EXPECT_LT(Spread(FrontCounts(maps, boundaries, in_counted_range)), 0.1);
  // The anchor search: one new sector holds the closed range (135 degrees)
  // and more; the other seven share the counted range. Every sector's rays
  // lie inside its span.
  SectorRays rays;
  ASSERT_TRUE(EquidistributedSectorRays(maps, kCol, kRow, kMaxDistance,
                                        kDefaultEquidistributionIterations,
                                        RecutWhere::kSomeSectorClosed, 4, &rays));
  int wide = 0;
  for (int k = 0; k < kNumSectors; ++k) {
    const double span = 2.0 * std::acos(rays.min_cos[k]) * 180.0 / kPi;
    wide += span > 135.0;
    for (int j = 0; j < rays.rays; ++j) {
      const RayDirection& ray = rays.ray[k * rays.rays + j];
      EXPECT_GE(ray.x * rays.centre[k].x + ray.y * rays.centre[k].y, rays.min_cos[k] - 1e-5f);
    }
  }
  EXPECT_EQ(wide, 1);
}

// Reliable pixels from 20 px on, and radial depth edges from 12 px out along
// the directions `walls` (degrees), up to 2 px either side: a ray along a
// wall stops on it at once, rays between the walls reach the reliable pixels.
Layout RadialWalls(const std::vector<double>& walls) {
  Layout layout;
  layout.Fill([](int dx, int dy) { return dx * dx + dy * dy > 20 * 20; });
  layout.Edges([&](int dx, int dy) {
    const int d2 = dx * dx + dy * dy;
    if (d2 < 12 * 12) return false;
    for (double wall : walls) {
      const double off = std::fabs(Wrap(AngleOf(dx, dy) - wall, -180.0));
      if (off * kPi / 180.0 * std::sqrt(d2) < 2.0) return true;
    }
    return false;
  });
  return layout;
}

// The fixed sectors' boundaries 22.5 + 45 k degrees.
std::vector<double> BoundaryWalls() {
  std::vector<double> walls;
  for (int k = 0; k < kNumSectors; ++k) walls.push_back(kFirstBoundaryDegrees + 45.0 * k);
  return walls;
}

// With no sector counting a reliable pixel the search keeps the fixed
// sectors exactly: no reliable pixel at all, or every boundary ray stopped by
// a depth edge (edges along the fixed sectors' boundaries, reliable pixels
// between them).
TEST(Equidistribution, NoCountKeepsTheFixedSectors) {
  SectorRays fixed, rays;
  std::memset(&fixed, 0, sizeof(fixed));
  FixedSectorRays(2, &fixed);
  const auto same = [&](const SectorRays& rays) {
    return std::memcmp(&rays, &fixed, sizeof(SectorRays)) == 0;
  };
  Layout empty;
  empty.Fill([](int, int) { return false; });
  std::memset(&rays, 0, sizeof(rays));
  EXPECT_FALSE(EquidistributedSectorRays(empty.Maps(), kCol, kRow, kMaxDistance, 2,
                                         RecutWhere::kEverywhere, 2, &rays));
  EXPECT_TRUE(same(rays));

  const Layout walled = RadialWalls(BoundaryWalls());
  std::memset(&rays, 0, sizeof(rays));
  EXPECT_FALSE(EquidistributedSectorRays(walled.Maps(), kCol, kRow, kMaxDistance, 2,
                                         RecutWhere::kEverywhere, 2, &rays));
  EXPECT_TRUE(same(rays));
  // The anchor search then finds the same hits as without equidistribution.
  AnchorParams params = DefaultAnchorParams(0, kDepthRange, kMaxDistance);
  AnchorHits off, on;
  CastAnchorHits(walled.Maps(), kCol, kRow, params, &off);
  params.equidistribution = true;
  CastAnchorHits(walled.Maps(), kCol, kRow, params, &on);
  ASSERT_GT(off.count, 0);
  ASSERT_EQ(on.count, off.count);
  EXPECT_EQ(on.num_sectors, off.num_sectors);
  for (int k = 0; k < on.count; ++k) EXPECT_EQ(on.index[k], off.index[k]);
}

// p in a small room walled by depth edges (radius 6-7.5 px) with two doors,
// east and west, 50 degrees wide; reliable pixels from 20 px on, all on one
// plane. The fixed sectors find hits only through the doors, in 2 of 8
// sectors: too few, p gets no anchors. Equidistribution cuts the doors into 4
// sectors each (the last one of each door also spans the wall up to the
// other door, where its rays find nothing): 6 sectors hit, and p gets anchors
// on the true plane, none behind the walls.
TEST(Equidistribution, RecoversAnchorsTheFixedSectorsMiss) {
  Layout layout;
  layout.Fill([](int dx, int dy) { return dx * dx + dy * dy >= 20 * 20; });
  const auto in_door = [](double degrees) {
    return std::fabs(degrees) < 25.0 || std::fabs(degrees) > 155.0;
  };
  layout.Edges([&](int dx, int dy) {
    const int d2 = dx * dx + dy * dy;
    return d2 >= 36 && d2 <= 56 && !in_door(AngleOf(dx, dy));
  });
  AnchorParams params = DefaultAnchorParams(0, kDepthRange, kMaxDistance);
  AnchorSet fixed, adaptive;
  Rng rng = MakeRng(7);
  EXPECT_FALSE(FindAnchors(layout.cam, layout.Maps(), kCol, kRow, params, &rng, &fixed));
  EXPECT_EQ(fixed.num_sectors, 2);
  params.equidistribution = true;
  rng = MakeRng(7);
  ASSERT_TRUE(FindAnchors(layout.cam, layout.Maps(), kCol, kRow, params, &rng, &adaptive));
  EXPECT_EQ(adaptive.num_sectors, 6);
  EXPECT_EQ(adaptive.count, kMaxAnchors);
  EXPECT_NEAR(AnchorPlaneHypothesis(layout.cam, adaptive, kCol, kRow).depth,
              layout.TrueDepth(kCol, kRow), 1e-3f);
  // Every ray hit lies in a door, in both doors, and none behind a wall.
  AnchorHits hits;
  CastAnchorHits(layout.Maps(), kCol, kRow, params, &hits);
  EXPECT_EQ(hits.count, 6 * params.rays_per_sector);
  int east = 0, west = 0;
  for (int k = 0; k < hits.count; ++k) {
    const int q = hits.index[k];
    const double angle = AngleOf(q % kSize - kCol, q / kSize - kRow);
    EXPECT_TRUE(in_door(angle)) << q % kSize << "," << q / kSize;
    EXPECT_FALSE(CrossesDepthEdge(layout.Maps(), kCol, kRow, q));
    east += std::fabs(angle) < 90.0;
    west += std::fabs(angle) > 90.0;
  }
  EXPECT_EQ(east, west);  // the two doors face equal counts
}

}  // namespace
}  // namespace core
}  // namespace msp
