#include "deformable/anchor_pair_cache.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/deformable/deformable_sweep_pixel.h"
#include "tests/support/plane_scene.h"

namespace msp {
namespace {

using core::kMaxAnchors;
using core::kMaxSourceViews;

TEST(AnchorPairCache, HoldsWhatWasStoredUntilCleared) {
  AnchorPairCache cache(9);
  const uint64_t key = AnchorPairCache::Key(1234, 5678);
  EXPECT_EQ(cache.Find(key), nullptr);
  float* slot = cache.Store(key);
  for (int j = 0; j < 9; ++j) slot[j] = 0.5f + j;
  const float* found = cache.Find(key);
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found[8], 8.5f);
  EXPECT_EQ(cache.Find(AnchorPairCache::Key(5678, 1234)), nullptr);  // pairs are ordered
  cache.Clear();
  EXPECT_EQ(cache.Find(key), nullptr);
}

// A textured plane seen by one source; the iteration's plane snapshot gives
// each anchor a plane of its own, so the anchors' candidates differ.
struct Fixture {
  test::PlaneScene s;
  std::vector<float> depth, normal;
  core::PlaneMapView planes;
  core::DeformableParams d = core::DefaultDeformableParams();

  Fixture() {
    test::MakeScene(4.0f, true, &s);
    depth = s.state_depth;
    normal = s.state_normal;
    const int n = s.ref.width * s.ref.height;
    for (int i = 0; i < n; ++i) {
      const core::Vec3 tilt =
          core::Normalized(core::Vec3{0.01f * (i % 7 - 3), 0.01f * (i % 5 - 2), -1.0f});
      depth[i] = 4.0f + 0.02f * (i % 3);
      normal[i] = tilt.x;
      normal[n + i] = tilt.y;
      normal[2 * n + i] = tilt.z;
    }
    planes = core::PlaneMapView{depth.data(), normal.data(), s.ref.width, s.ref.height};
  }

  // One anchor per sector around (col, row), `spread` px out.
  core::AnchorSet Ring(int col, int row, int spread) const {
    const int dirs[kMaxAnchors][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                      {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    core::AnchorSet a{};
    a.count = kMaxAnchors;
    for (int k = 0; k < kMaxAnchors; ++k) {
      a.cols[k] = col + spread * dirs[k][0];
      a.rows[k] = row + spread * dirs[k][1];
    }
    return a;
  }

  // The anchor sums of the pixel's anchors' candidates from `provider`.
  template <typename Provider>
  core::CandidateAnchorSums Sums(int col, int row, const core::AnchorSet& anchors,
                                 const Provider& provider) const {
    core::DeformableWindows w;
    core::PrepareDeformableWindows(s.params, col, row, anchors, d, &w);
    core::PreparedPlane prepared[kMaxAnchors];
    uint32_t need[kMaxAnchors];
    for (int k = 0; k < kMaxAnchors; ++k) {
      const core::PlaneHypothesis h = planes.Get(anchors.rows[k] * s.ref.width + anchors.cols[k]);
      const core::PlaneHypothesis candidate{
          core::PropagatedDepth(s.ref, anchors.cols[k], anchors.rows[k], h, col, row), h.normal};
      prepared[k] = core::PreparePlane(s.params, col, row, candidate);
      need[k] = 1u;  // the one source view
    }
    core::CandidateAnchorSums sums;
    provider(w.anchors, prepared, need, &sums);
    return sums;
  }
};

// The cache's sums agree with the sums computed on the spot, and are the
// same to the bit whether the pairs were computed now or read back from an
// earlier pixel's update: results cannot depend on what the cache holds.
TEST(CachedAnchorSums, SameSumsWhateverTheCacheHolds) {
  const Fixture f;
  const int col = 100, row = 75;
  const core::AnchorSet anchors = f.Ring(col, row, 20);
  const core::CandidateAnchorSums direct =
      f.Sums(col, row, anchors, core::DirectAnchorSums{f.s.params, f.d});
  AnchorPairCache fresh(f.s.params.num_src);
  const core::CandidateAnchorSums first =
      f.Sums(col, row, anchors, CachedAnchorSums(f.s.params, f.planes, f.d, &fresh));
  // A neighbour shares 5 of the 8 anchors; it fills another cache first.
  core::AnchorSet neighbours = f.Ring(col + 2, row, 20);
  for (int k = 0; k < 5; ++k) {
    neighbours.cols[k] = anchors.cols[k];
    neighbours.rows[k] = anchors.rows[k];
  }
  AnchorPairCache warm(f.s.params.num_src);
  const CachedAnchorSums from_warm(f.s.params, f.planes, f.d, &warm);
  f.Sums(col + 2, row, neighbours, from_warm);
  const int width = f.s.ref.width;
  const uint64_t shared = AnchorPairCache::Key(anchors.rows[1] * width + anchors.cols[1],
                                               anchors.rows[3] * width + anchors.cols[3]);
  ASSERT_NE(warm.Find(shared), nullptr);
  const core::CandidateAnchorSums second = f.Sums(col, row, anchors, from_warm);
  // And once more from the same cache, now holding every pair.
  const core::CandidateAnchorSums third = f.Sums(col, row, anchors, from_warm);
  for (int k = 0; k < kMaxAnchors; ++k) {
    EXPECT_NEAR(first.sum[k][0], direct.sum[k][0], 1e-4f) << k;
    EXPECT_EQ(second.sum[k][0], first.sum[k][0]) << k;
    EXPECT_EQ(third.sum[k][0], first.sum[k][0]) << k;
  }
  // The sums are real: the anchors match their planes (near the truth) far
  // better than the worst cost of 2 per anchor.
  EXPECT_LT(first.sum[0][0], 0.5f * kMaxAnchors * core::kMaxCost);
}

// The CUDA back-end's provider, which scores every pair on the spot under
// its anchor's own plane, gives the cache's sums to the bit, whether the
// cache computed its pairs now or reads them back, and a deformable update
// through each ends alike: the two back-ends' updates take the same sums.
TEST(OwnPlaneAnchorSums, TheCachesSumsToTheBit) {
  Fixture f;
  const int col = 100, row = 75;
  const core::AnchorSet anchors = f.Ring(col, row, 20);
  const core::OwnPlaneAnchorSums own{f.s.params, f.planes, f.d};
  const core::CandidateAnchorSums expected = f.Sums(col, row, anchors, own);
  AnchorPairCache cache(f.s.params.num_src);
  const CachedAnchorSums cached(f.s.params, f.planes, f.d, &cache);
  const core::CandidateAnchorSums from_cold = f.Sums(col, row, anchors, cached);
  const core::CandidateAnchorSums from_warm = f.Sums(col, row, anchors, cached);  // read back
  for (int k = 0; k < kMaxAnchors; ++k) {
    EXPECT_EQ(from_cold.sum[k][0], expected.sum[k][0]) << k;
    EXPECT_EQ(from_warm.sum[k][0], expected.sum[k][0]) << k;
  }
  EXPECT_LT(expected.sum[0][0], 0.5f * kMaxAnchors * core::kMaxCost);

  test::PlaneScene& s = f.s;
  const int i = row * s.ref.width + col;
  s.state_depth[i] = 3.6f;
  s.state_cost[i] = core::kMaxCost;
  const std::vector<float> start_depth = s.state_depth, start_normal = s.state_normal;
  core::DeformableUpdatePixel(s.params, col, row, 0, anchors, f.planes, f.d, own);
  const float own_depth = s.state_depth[i], own_cost = s.state_cost[i];
  s.state_depth = start_depth;
  s.state_normal = start_normal;
  s.state_cost[i] = core::kMaxCost;
  cache.Clear();
  core::DeformableUpdatePixel(s.params, col, row, 0, anchors, f.planes, f.d, cached);
  EXPECT_EQ(s.state_depth[i], own_depth);
  EXPECT_EQ(s.state_cost[i], own_cost);
}

// A deformable update gives the same plane and cost with the cache as with
// the anchor sums computed on the spot, up to float rounding.
TEST(CachedAnchorSums, DeformableUpdateAsWithDirectSums) {
  Fixture f;
  const int col = 100, row = 75;
  const core::AnchorSet anchors = f.Ring(col, row, 20);
  const int i = row * f.s.ref.width + col;
  f.s.state_depth[i] = 3.6f;  // a wrong start: the anchors' planes must win
  f.s.state_cost[i] = core::kMaxCost;
  test::PlaneScene& s = f.s;
  const std::vector<float> start_depth = s.state_depth, start_normal = s.state_normal;
  core::DeformableUpdatePixel(s.params, col, row, 0, anchors, f.planes, f.d);
  const float direct_depth = s.state_depth[i], direct_cost = s.state_cost[i];
  s.state_depth = start_depth;
  s.state_normal = start_normal;
  s.state_cost[i] = core::kMaxCost;
  AnchorPairCache cache(s.params.num_src);
  core::DeformableUpdatePixel(s.params, col, row, 0, anchors, f.planes, f.d,
                              CachedAnchorSums(s.params, f.planes, f.d, &cache));
  EXPECT_NEAR(s.state_depth[i], direct_depth, 1e-4f);
  EXPECT_NEAR(s.state_cost[i], direct_cost, 1e-4f);
  EXPECT_NEAR(s.state_depth[i], 4.0f, 0.1f);
}

}  // namespace
}  // namespace msp
