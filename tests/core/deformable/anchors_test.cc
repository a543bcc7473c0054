#include "core/deformable/anchors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "base/nearest_marked_pixels.h"
#include "tests/support/cameras.h"
#include "tests/support/images.h"

namespace msp {
namespace core {
namespace {

constexpr int kSize = 120;
constexpr int kCol = 60, kRow = 60;  // the unreliable pixel p
constexpr float kDepthRange = 10.0f;
constexpr int kMaxDistance = 100;
constexpr float kPi = 3.14159265f;

// The whole anchor search for pixel (col, row), as the deformable sweeps run
// it: the rays, then the RANSAC fit.
bool FindAnchors(const Camera& cam, const AnchorMaps& maps, int col, int row,
                 const AnchorParams& params, Rng* rng, AnchorSet* out) {
  AnchorHits hits;
  CastAnchorHits(maps, col, row, params, &hits);
  return FitAnchors(cam, maps, col, row, params, hits, rng, out);
}

// A reference camera and the slanted plane every reliable pixel lies on.
struct Layout {
  Camera cam = test::SkewedIntrinsicsCamera(kSize, kSize, 100.0f, test::Identity(), Vec3{0, 0, 0});
  Vec3 normal = Normalized(Vec3{0.2f, -0.1f, -1.0f});
  float dist = 5.0f;
  std::vector<uint8_t> classes = std::vector<uint8_t>(kSize * kSize, kUnreliable);
  std::vector<float> depth = std::vector<float>(kSize * kSize, 0.0f);
  std::vector<int> nearest;

  float TrueDepth(float c, float r) const { return DepthOnPlane(cam, normal, dist, c, r); }

  // Pixels where `reliable(dx, dy, angle_degrees)` holds become reliable on the plane.
  void Fill(const std::function<bool(int, int, float)>& reliable) {
    for (int r = 0; r < kSize; ++r) {
      for (int c = 0; c < kSize; ++c) {
        const int dx = c - kCol, dy = r - kRow;
        const float angle =
            std::atan2(static_cast<float>(dy), static_cast<float>(dx)) * 180.0f / kPi;
        if (!(dx == 0 && dy == 0) && reliable(dx, dy, angle)) {
          classes[r * kSize + c] = kReliable;
          depth[r * kSize + c] = TrueDepth(c, r);
        }
      }
    }
    nearest = NearestReliablePixels(classes.data(), kSize, kSize, 1);
  }

  AnchorMaps Maps() const {
    return AnchorMaps{classes.data(), nearest.data(), depth.data(),
                      kSize,          kSize,          BoundaryView{nullptr, 0, 0, 0}};
  }

  bool Find(int round, AnchorSet* out, uint64_t key = 7) const {
    Rng rng = MakeRng(key);
    return FindAnchors(cam, Maps(), kCol, kRow,
                       DefaultAnchorParams(round, kDepthRange, kMaxDistance), &rng, out);
  }

  // The same search confined by the depth-edge map `edges` (1 = edge).
  bool FindConfined(const test::EdgeMap& edges, AnchorSet* out) const {
    AnchorMaps maps = Maps();
    maps.edges = edges.View();
    Rng rng = MakeRng(7);
    return FindAnchors(cam, maps, kCol, kRow, DefaultAnchorParams(0, kDepthRange, kMaxDistance),
                       &rng, out);
  }
};

// The same anchors, in the same order.
void ExpectSameAnchors(const AnchorSet& a, const AnchorSet& b) {
  ASSERT_EQ(a.count, b.count);
  for (int k = 0; k < a.count; ++k) {
    EXPECT_EQ(a.cols[k], b.cols[k]) << "anchor " << k;
    EXPECT_EQ(a.rows[k], b.rows[k]) << "anchor " << k;
  }
}

// Reliable outside a disk of radius 20 around p: a textureless blob.
bool OutsideDisk(int dx, int dy, float) { return dx * dx + dy * dy > 20 * 20; }

TEST(Anchors, ScheduleOfRaysAndThresholds) {
  EXPECT_EQ(RaysPerSector(0), 2);
  EXPECT_EQ(RaysPerSector(1), 4);
  EXPECT_EQ(RaysPerSector(5), kMaxRaysPerSector);
  EXPECT_FLOAT_EQ(AnchorInlierThreshold(0, 10.0f), 0.1f);
  EXPECT_FLOAT_EQ(AnchorInlierThreshold(2, 10.0f), 0.075f);
  EXPECT_GT(AnchorInlierThreshold(20, 10.0f), 0.0f);
  int radius = kFirstRayRadius;
  const int expected[] = {2, 4, 8, 16, 32, 57, 82};
  for (int e : expected) {
    EXPECT_EQ(radius, e);
    radius = NextRayRadius(radius);
  }
}

TEST(Anchors, TriangleContainment) {
  EXPECT_TRUE(TriangleContains(0, 0, 10, 0, 0, 10, 2, 2));
  EXPECT_TRUE(TriangleContains(0, 0, 0, 10, 10, 0, 2, 2));  // either winding
  EXPECT_TRUE(TriangleContains(0, 0, 10, 0, 0, 10, 5, 5));  // on an edge
  EXPECT_FALSE(TriangleContains(0, 0, 10, 0, 0, 10, 6, 6));
  EXPECT_FALSE(TriangleContains(0, 0, 10, 0, 0, 10, -1, 2));
}

TEST(Anchors, EverySectorHitsAndThePlaneIsRecovered) {
  for (int round = 0; round < 2; ++round) {
    Layout layout;
    layout.Fill(OutsideDisk);
    AnchorSet a;
    ASSERT_TRUE(layout.Find(round, &a));
    EXPECT_EQ(a.num_sectors, kNumSectors);
    EXPECT_EQ(a.count, kMaxAnchors);
    EXPECT_EQ(a.num_inliers, kNumSectors * RaysPerSector(round));
    const PlaneHypothesis h = AnchorPlaneHypothesis(layout.cam, a, kCol, kRow);
    EXPECT_NEAR(h.depth, layout.TrueDepth(kCol, kRow), 1e-3f);
    EXPECT_GT(Dot(h.normal, layout.normal), 0.9999f);
    for (int k = 0; k < a.count; ++k) {
      EXPECT_EQ(layout.classes[a.rows[k] * kSize + a.cols[k]], kReliable);
      const int dx = a.cols[k] - kCol, dy = a.rows[k] - kRow;
      EXPECT_GT(dx * dx + dy * dy, 20 * 20);
      EXPECT_LE(dx * dx + dy * dy, kMaxDistance * kMaxDistance);
    }
  }
}

TEST(Anchors, UnreliableHitsSnapInsideTheirSector) {
  // Reliable pixels only on a ring: every ray position at radius 32 is off the
  // ring (29..31 px) except by snapping.
  Layout layout;
  layout.Fill([](int dx, int dy, float) {
    const int d2 = dx * dx + dy * dy;
    return d2 >= 29 * 29 && d2 <= 31 * 31;
  });
  AnchorSet a;
  ASSERT_TRUE(layout.Find(0, &a));
  EXPECT_EQ(a.num_sectors, kNumSectors);
  for (int k = 0; k < a.count; ++k) {
    EXPECT_EQ(layout.classes[a.rows[k] * kSize + a.cols[k]], kReliable);
  }
}

TEST(Anchors, RansacRejectsHitsOnAnotherSurface) {
  Layout layout;
  layout.Fill(OutsideDisk);
  // Two sectors see a surface 30% deeper: those hits are outliers.
  auto outlier = [](float angle) {
    return std::fabs(angle - 90.0f) < 30.0f || std::fabs(angle + 135.0f) < 30.0f;
  };
  for (int r = 0; r < kSize; ++r) {
    for (int c = 0; c < kSize; ++c) {
      const float angle =
          std::atan2(static_cast<float>(r - kRow), static_cast<float>(c - kCol)) * 180.0f / kPi;
      if (layout.depth[r * kSize + c] > 0.0f && outlier(angle)) layout.depth[r * kSize + c] *= 1.3f;
    }
  }
  AnchorSet a;
  ASSERT_TRUE(layout.Find(0, &a));
  EXPECT_EQ(a.num_sectors, kNumSectors);
  EXPECT_EQ(a.count, kMaxAnchors);
  // At most the 2 rays of each of the 6 clean sectors (snapping near the wedge
  // edges may move a few hits onto the deeper surface).
  EXPECT_GE(a.num_inliers, kDefaultMinInliers);
  EXPECT_LE(a.num_inliers, 2 * (kNumSectors - 2));
  EXPECT_NEAR(AnchorPlaneHypothesis(layout.cam, a, kCol, kRow).depth, layout.TrueDepth(kCol, kRow),
              1e-3f);
  for (int k = 0; k < a.count; ++k) {
    const float angle =
        std::atan2(static_cast<float>(a.rows[k] - kRow), static_cast<float>(a.cols[k] - kCol)) *
        180.0f / kPi;
    EXPECT_FALSE(outlier(angle)) << "anchor " << a.cols[k] << "," << a.rows[k];
  }
}

TEST(Anchors, TooFewSectorsIsUnknown) {
  Layout layout;
  layout.Fill([](int dx, int, float) { return dx < -30; });  // a reliable strip on the left
  AnchorSet a;
  EXPECT_FALSE(layout.Find(0, &a));
  EXPECT_LT(a.num_sectors, kDefaultMinSectors);
  EXPECT_EQ(a.count, 0);
}

TEST(Anchors, TrianglesMustContainThePixel) {
  // Reliable pixels only within a 170-degree wedge: four sectors hit, but no
  // triangle of hits contains p, so no plane is accepted.
  Layout layout;
  layout.Fill([](int dx, int dy, float angle) {
    return dx * dx + dy * dy > 100 && angle >= -20.0f && angle <= 150.0f;
  });
  AnchorSet a;
  EXPECT_FALSE(layout.Find(0, &a));
  EXPECT_EQ(a.num_sectors, 4);
  EXPECT_EQ(a.num_inliers, 0);
  EXPECT_EQ(a.count, 0);
}

// Edge confinement (docs/method.md section 4.2): the reliable pixels right of a
// depth edge 15 px east of p are ray hits of the unconfined search and none
// of the confined one; those on p's side stay hits and anchors.
TEST(Anchors, DepthEdgeRejectsHitsBehindItAndKeepsThoseInside) {
  constexpr int kEdgeCol = kCol + 15;
  Layout layout;
  layout.Fill(OutsideDisk);
  const AnchorParams params = DefaultAnchorParams(0, kDepthRange, kMaxDistance);
  const test::EdgeMap edges = test::VerticalEdge(kSize, kSize, kEdgeCol);
  AnchorMaps confined_maps = layout.Maps();
  confined_maps.edges = edges.View();

  int free_hits[kMaxAnchorHits], confined_hits[kMaxAnchorHits];
  int free_sectors = 0, confined_sectors = 0;
  const int num_free =
      CollectAnchorHits(layout.Maps(), kCol, kRow, params, free_hits, &free_sectors);
  const int num_confined =
      CollectAnchorHits(confined_maps, kCol, kRow, params, confined_hits, &confined_sectors);
  int behind = 0;
  for (int k = 0; k < num_free; ++k) behind += free_hits[k] % kSize >= kEdgeCol;
  ASSERT_GT(behind, 0) << "the unconfined search must reach behind the edge";
  EXPECT_EQ(free_sectors, kNumSectors);
  EXPECT_EQ(confined_sectors, kNumSectors - 1);  // the east sector lies behind the edge
  // Every hit on p's side is kept, every hit behind the edge is gone.
  EXPECT_EQ(num_confined, num_free - behind);
  for (int k = 0; k < num_confined; ++k) EXPECT_LT(confined_hits[k] % kSize, kEdgeCol);

  AnchorSet confined;
  ASSERT_TRUE(layout.FindConfined(edges, &confined));
  ASSERT_EQ(confined.count, kMaxAnchors);
  for (int k = 0; k < confined.count; ++k) {
    EXPECT_LT(confined.cols[k], kEdgeCol)
        << "anchor " << confined.cols[k] << "," << confined.rows[k];
  }
  // The confined anchors still span the true plane through p.
  EXPECT_NEAR(AnchorPlaneHypothesis(layout.cam, confined, kCol, kRow).depth,
              layout.TrueDepth(kCol, kRow), 1e-3f);

  // A confined search on an edge map without edges is the unconfined one.
  AnchorSet free_set, no_edges;
  ASSERT_TRUE(layout.Find(0, &free_set));
  ASSERT_TRUE(layout.FindConfined(test::NoEdges(kSize, kSize), &no_edges));
  ExpectSameAnchors(no_edges, free_set);
}

// A snapped hit behind an edge is skipped, not taken: reliable pixels only on
// a ring (reached by snapping), with an edge cutting the ring's east side.
TEST(Anchors, SnappedHitsBehindAnEdgeAreSkipped) {
  Layout layout;
  layout.Fill([](int dx, int dy, float) {
    const int d2 = dx * dx + dy * dy;
    return d2 >= 29 * 29 && d2 <= 31 * 31;
  });
  constexpr int kEdgeCol = kCol + 20;
  AnchorSet confined;
  layout.FindConfined(test::VerticalEdge(kSize, kSize, kEdgeCol), &confined);
  EXPECT_LT(confined.num_sectors, kNumSectors);
  for (int k = 0; k < confined.count; ++k) EXPECT_LT(confined.cols[k], kEdgeCol);
}

TEST(Anchors, SameKeySameAnchors) {
  Layout layout;
  layout.Fill(OutsideDisk);
  AnchorSet a, b;
  ASSERT_TRUE(layout.Find(1, &a, 42));
  ASSERT_TRUE(layout.Find(1, &b, 42));
  ExpectSameAnchors(a, b);
}

TEST(Anchors, HitsCastOnceRefitOnNewDepths) {
  // The sweeps cast the rays once per pass and refit every iteration: the
  // refit on unchanged depths is the full search, and moved depths move the plane.
  Layout layout;
  layout.Fill(OutsideDisk);
  const AnchorParams params = DefaultAnchorParams(0, kDepthRange, kMaxDistance);
  AnchorHits hits;
  CastAnchorHits(layout.Maps(), kCol, kRow, params, &hits);
  EXPECT_TRUE(HitsStillValid(layout.Maps(), hits));
  AnchorSet full, refit;
  ASSERT_TRUE(layout.Find(0, &full));
  Rng rng = MakeRng(7);
  ASSERT_TRUE(FitAnchors(layout.cam, layout.Maps(), kCol, kRow, params, hits, &rng, &refit));
  ExpectSameAnchors(refit, full);
  for (float& d : layout.depth) d *= 1.1f;  // the whole surface 10 % farther
  rng = MakeRng(7);
  ASSERT_TRUE(FitAnchors(layout.cam, layout.Maps(), kCol, kRow, params, hits, &rng, &refit));
  EXPECT_NEAR(AnchorPlaneHypothesis(layout.cam, refit, kCol, kRow).depth,
              1.1f * layout.TrueDepth(kCol, kRow), 2e-3f);
  // A hit that lost its depth sends the pixel back to the rays.
  layout.depth[hits.index[0]] = 0.0f;
  EXPECT_FALSE(HitsStillValid(layout.Maps(), hits));
}

// Disassemble-clustering keeps every inlier: APD's anchors first (the same
// RANSAC draws give the same plane), then the other inliers, all sorted by
// distance to the plane and all within the threshold.
TEST(Anchors, EveryInlierKeptWithApdsAnchorsFirst) {
  Layout layout;
  layout.Fill(OutsideDisk);
  AnchorParams params = DefaultAnchorParams(2, kDepthRange, kMaxDistance);
  AnchorHits hits;
  CastAnchorHits(layout.Maps(), kCol, kRow, params, &hits);
  AnchorSet apd, all;
  Rng rng = MakeRng(7);
  ASSERT_TRUE(FitAnchors(layout.cam, layout.Maps(), kCol, kRow, params, hits, &rng, &apd));
  params.max_anchors = kMaxKeptAnchors;
  rng = MakeRng(7);
  ASSERT_TRUE(FitAnchors(layout.cam, layout.Maps(), kCol, kRow, params, hits, &rng, &all));
  ASSERT_EQ(apd.count, kMaxAnchors);
  EXPECT_EQ(all.count, all.num_inliers);
  EXPECT_GT(all.count, 3 * kMaxAnchors);  // every ray of this layout hits the plane
  for (int k = 0; k < kMaxAnchors; ++k) {
    EXPECT_EQ(all.cols[k], apd.cols[k]) << k;
    EXPECT_EQ(all.rows[k], apd.rows[k]) << k;
  }
  float previous = 0.0f;
  for (int k = 0; k < all.count; ++k) {
    const int q = all.rows[k] * kSize + all.cols[k];
    const Vec3 X = BackProject(layout.cam, static_cast<float>(all.cols[k]),
                               static_cast<float>(all.rows[k]), layout.depth[q]);
    const float e = std::fabs(Dot(all.plane_normal, X) + all.plane_dist);
    EXPECT_LE(e, params.inlier_threshold);
    EXPECT_GE(e, previous);
    previous = e;
  }
}

// The nearest-edge map only skips walks that cannot reach an edge: on random
// reliable pixels and random edge segments, every pixel's confined hits are
// the same with it as without it, and some hits were confined away.
TEST(Anchors, NearestEdgeMapLeavesTheConfinedHitsAsTheyAre) {
  Layout layout;
  layout.Fill([](int dx, int dy, float) {
    const uint32_t h = static_cast<uint32_t>((dx + 200) * 7919 + (dy + 200) * 104729);
    return (h * 2654435761u) >> 28 == 0;  // about one pixel in 16
  });
  test::EdgeMap edges = test::NoEdges(kSize, kSize);
  Rng rng = MakeRng(11);
  for (int segment = 0; segment < 12; ++segment) {  // short straight edges, 2 px wide
    const int c = static_cast<int>(rng.Uniform(0.0f, kSize - 30.0f));
    const int r = static_cast<int>(rng.Uniform(0.0f, kSize - 30.0f));
    const bool vertical = rng.Uniform() < 0.5f;
    for (int k = 0; k < 30; ++k) {
      for (int w = 0; w < 2; ++w) {
        edges.bits[vertical ? (r + k) * kSize + c + w : (r + w) * kSize + c + k] = 1;
      }
    }
  }
  const std::vector<int> nearest_edge = NearestMarkedPixels(edges.bits.data(), kSize, kSize, 1);
  AnchorMaps plain = layout.Maps();
  plain.edges = edges.View();
  AnchorMaps shortcut = plain;
  shortcut.nearest_edge = nearest_edge.data();
  const AnchorParams params = DefaultAnchorParams(3, kDepthRange, kMaxDistance);
  int confined_away = 0;
  for (int row = 0; row < kSize; row += 3) {
    for (int col = 0; col < kSize; col += 3) {
      AnchorHits a, b, free;
      CastAnchorHits(plain, col, row, params, &a);
      CastAnchorHits(shortcut, col, row, params, &b);
      CastAnchorHits(layout.Maps(), col, row, params, &free);
      ASSERT_EQ(a.count, b.count) << col << "," << row;
      EXPECT_EQ(a.num_sectors, b.num_sectors);
      for (int k = 0; k < a.count; ++k) EXPECT_EQ(a.index[k], b.index[k]);
      confined_away += free.count - a.count;
    }
  }
  EXPECT_GT(confined_away, 100);
}

}  // namespace
}  // namespace core
}  // namespace msp
