// UpdatePixel (patch_match_kernel.h) on the textured plane z = 4: one
// red-black update of one pixel, its neighbours' planes given.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"
#include "tests/support/plane_scene.h"

namespace msp {
namespace core {
namespace {

constexpr float kDepth = 4.0f;
constexpr int kCol = 100, kRow = 75;  // far enough from the border for every region
const Vec3 kFrontoParallel{0.0f, 0.0f, -1.0f};
// The refinement's perturbations as the CPU driver sets them.
constexpr float kPerturbDepth = 0.02f;
constexpr float kPerturbNormal = 1.8f * 3.14159265f / 180.0f;
// Iterations of a pixel left to the refinement alone.
constexpr int kRefineIterations = 20;

// Every pixel of the state's cost, as after initialisation.
void ScoreAll(const PassParams& p) {
  for (int row = 0; row < p.state.height; ++row) {
    for (int col = 0; col < p.state.width; ++col) ScorePixel(p, col, row);
  }
}

// The plane scene with the refinement's perturbations, every pixel on the
// true plane and scored.
void MakeScoredScene(test::PlaneScene* s) {
  test::MakeScene(kDepth, true, s);
  s->params.perturb_depth = kPerturbDepth;
  s->params.perturb_normal = kPerturbNormal;
  s->params.seed = 5;
  ScoreAll(s->params);
}

PlaneHypothesis PlaneAt(const PassParams& p, int col, int row) {
  return p.state.Get(p.state.Index(col, row));
}

float StoredCost(const PassParams& p, int col, int row) {
  return p.state.cost[p.state.Index(col, row)];
}

// The neighbours propose the true plane: a pixel on a wrong plane (10 % too
// deep and tilted) takes it, and its cost falls to the true plane's.
TEST(UpdatePixel, PropagationReplacesAWrongPlaneWithTheTrueOne) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  const PassParams& p = s.params;
  const int i = p.state.Index(kCol, kRow);
  p.state.Set(i, PlaneHypothesis{1.1f * kDepth, Normalized(Vec3{0.3f, -0.2f, -1.0f})});
  ScorePixel(p, kCol, kRow);
  const float wrong_cost = StoredCost(p, kCol, kRow);
  ASSERT_GT(wrong_cost, 0.5f);  // the wrong plane does not match

  UpdatePixel(p, kCol, kRow, /*iteration=*/0);
  const PlaneHypothesis h = PlaneAt(p, kCol, kRow);
  EXPECT_NEAR(h.depth, kDepth, /*max_rel_depth_error=*/0.01f * kDepth);
  EXPECT_GT(Dot(h.normal, kFrontoParallel), std::cos(2.0f * kPerturbNormal));
  EXPECT_LT(StoredCost(p, kCol, kRow), 0.1f);
  EXPECT_EQ(p.state.mask[i], 1u);  // the one source view, which matches
}

// Without neighbours only the refinement proposes planes: over iterations
// it walks a plane 3 % too deep to the true one, and with one view (whose
// weight is always 1) the stored cost never rises.
TEST(UpdatePixel, RefinementAloneMovesAnIsolatedPlaneToTheTrueOne) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  const PassParams& p = s.params;
  for (float& d : s.state_depth) d = 0.0f;  // no plane around
  const int i = p.state.Index(kCol, kRow);
  p.state.Set(i, PlaneHypothesis{1.03f * kDepth, kFrontoParallel});
  ScorePixel(p, kCol, kRow);
  float cost = StoredCost(p, kCol, kRow);
  for (int iteration = 0; iteration < kRefineIterations; ++iteration) {
    UpdatePixel(p, kCol, kRow, iteration);
    EXPECT_LE(StoredCost(p, kCol, kRow), cost) << "iteration " << iteration;
    cost = StoredCost(p, kCol, kRow);
  }
  EXPECT_NEAR(PlaneAt(p, kCol, kRow).depth, kDepth, /*max_rel_depth_error=*/0.005f * kDepth);
  EXPECT_LT(cost, 0.1f);
}

// Every candidate lies on the true plane and the refinement only proposes
// planes off it (no perturbation leaves a candidate where it was): the
// pixel keeps the true plane exactly.
TEST(UpdatePixel, KeepsTheTruePlaneWhenItIsTheBestCandidate) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  s.params.perturb_depth = 0.0f;
  s.params.perturb_normal = 0.0f;
  const PassParams& p = s.params;
  for (int row = 40; row <= 110; row += 14) {
    for (int col = 40; col <= 160; col += 24) {
      UpdatePixel(p, col, row, /*iteration=*/1);
      const PlaneHypothesis h = PlaneAt(p, col, row);
      EXPECT_NEAR(h.depth, kDepth, 1e-5f * kDepth) << col << "," << row;
      EXPECT_NEAR(h.normal.x, 0.0f, 1e-6f) << col << "," << row;
      EXPECT_NEAR(h.normal.y, 0.0f, 1e-6f) << col << "," << row;
      EXPECT_NEAR(h.normal.z, -1.0f, 1e-6f) << col << "," << row;
    }
  }
}

// With one source view the aggregate is that view's cost: the stored cost is
// the cost of the stored plane, in a photometric pass and in a geometric
// pass (where it includes the geometric term).
TEST(UpdatePixel, StoredCostIsTheCostOfTheStoredPlane) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  // A source depth map of another plane: the geometric term is large.
  const std::vector<float> other_plane = test::PlaneDepthMap(s.src, 1.05f * kDepth);
  for (const int geometric : {0, 1}) {
    s.params.geometric = geometric;
    s.params.src[0].depth =
        geometric ? ImageView{other_plane.data(), s.src.width, s.src.height, s.src.width}
                  : ImageView{nullptr, 0, 0, 0};
    const PassParams& p = s.params;
    PassParams photometric = p;
    photometric.geometric = 0;
    ScoreAll(p);
    int with_geometric_term = 0;
    for (int row = 30; row <= 120; row += 15) {
      for (int col = 30; col <= 170; col += 20) {
        UpdatePixel(p, col, row, /*iteration=*/2);
        const PlaneHypothesis h = PlaneAt(p, col, row);
        const float cost = test::ConventionalViewCost(p, 0, col, row, h);
        EXPECT_NEAR(StoredCost(p, col, row), cost, 1e-5f)
            << col << "," << row << " geometric " << geometric;
        with_geometric_term +=
            cost > test::ConventionalViewCost(photometric, 0, col, row, h) + 1e-3f;
      }
    }
    // In the geometric pass the term was part of the costs.
    EXPECT_EQ(with_geometric_term > 30, geometric == 1) << with_geometric_term;
  }
}

// No plane here and none around (no depth anywhere): the pixel starts afresh
// with a random plane in the depth range, and stores that plane's cost.
TEST(UpdatePixel, RestartsWithARandomPlaneWhenNothingIsAround) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  const PassParams& p = s.params;
  for (float& d : s.state_depth) d = 0.0f;
  for (const int col : {60, 100, 140}) {
    UpdatePixel(p, col, kRow, /*iteration=*/0);
    const PlaneHypothesis h = PlaneAt(p, col, kRow);
    EXPECT_GE(h.depth, p.depth_min);
    EXPECT_LE(h.depth, p.depth_max);
    EXPECT_NEAR(Norm(h.normal), 1.0f, 1e-5f);
    EXPECT_LT(Dot(h.normal, ViewRay(p.ref_camera, col, kRow)), 0.0f);  // facing the camera
    EXPECT_NEAR(StoredCost(p, col, kRow), test::ConventionalViewCost(p, 0, col, kRow, h), 1e-5f)
        << col;
  }
}

// A second source sees the plane's negative (as an occluder would break the
// match): it costs ~2 for every candidate, so view selection never draws it.
// The mask leaves it out and the stored cost is the first view's alone.
TEST(UpdatePixel, ViewSelectionLeavesOutAViewThatMatchesNoCandidate) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  const int negative = test::AddSourceView(test::MirroredSourceCamera(), &s);
  for (float& v : s.src_images.back().data) v = 1.0f - v;
  const PassParams& p = s.params;
  ScoreAll(p);
  for (const int col : {70, 100, 130}) {
    const int i = p.state.Index(col, kRow);
    p.state.Set(i, PlaneHypothesis{0.9f * kDepth, kFrontoParallel});
    UpdatePixel(p, col, kRow, /*iteration=*/0);
    const PlaneHypothesis h = PlaneAt(p, col, kRow);
    EXPECT_NEAR(h.depth, kDepth, 0.01f * kDepth) << col;
    EXPECT_EQ(p.state.mask[i], 1u) << col;
    EXPECT_GT(test::ConventionalViewCost(p, negative, col, kRow, h), 1.5f) << col;
    EXPECT_NEAR(StoredCost(p, col, kRow), test::ConventionalViewCost(p, 0, col, kRow, h), 1e-5f)
        << col;
  }
}

// Two sources that both see the plane: the stored cost is a weighted mean of
// the selected views' costs of the stored plane, so it lies between them.
TEST(UpdatePixel, StoredCostIsAMeanOfTheSelectedViews) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  test::AddSourceView(test::MirroredSourceCamera(), &s);
  for (uint32_t& m : s.state_mask) m = 3u;  // both views selected last time
  const PassParams& p = s.params;
  ScoreAll(p);
  int both = 0;
  for (int row = 40; row <= 110; row += 10) {
    for (int col = 50; col <= 150; col += 20) {
      UpdatePixel(p, col, row, /*iteration=*/1);
      const PlaneHypothesis h = PlaneAt(p, col, row);
      const uint32_t mask = p.state.mask[p.state.Index(col, row)];
      ASSERT_NE(mask, 0u);
      float lo = 1e30f, hi = -1e30f;
      for (int j = 0; j < 2; ++j) {
        if (!((mask >> j) & 1u)) continue;
        const float c = test::ConventionalViewCost(p, j, col, row, h);
        lo = fminf(lo, c);
        hi = fmaxf(hi, c);
      }
      EXPECT_GE(StoredCost(p, col, row), lo - 1e-5f) << col << "," << row;
      EXPECT_LE(StoredCost(p, col, row), hi + 1e-5f) << col << "," << row;
      both += mask == 3u;
    }
  }
  EXPECT_GT(both, 20);  // both views were selected at most pixels
}

// Two sources that both see the plane, and view 0 alone selected last time.
// With weighted_views_only the candidates are scored on view 0 only, so the
// selection stays {0} and the stored cost is view 0's; scoring every view,
// view selection draws view 1 again at some pixels.
TEST(UpdatePixel, WeightedViewsOnlyScoresTheLastSelection) {
  for (const int weighted_views_only : {0, 1}) {
    test::PlaneScene s;
    MakeScoredScene(&s);
    test::AddSourceView(test::MirroredSourceCamera(), &s);
    s.params.weighted_views_only = weighted_views_only;
    const PassParams& p = s.params;
    ScoreAll(p);
    for (uint32_t& m : s.state_mask) m = 1u;
    int redrawn = 0;
    for (int row = 40; row <= 110; row += 10) {
      for (int col = 50; col <= 150; col += 20) {
        UpdatePixel(p, col, row, /*iteration=*/1);
        const uint32_t mask = p.state.mask[p.state.Index(col, row)];
        redrawn += (mask & 2u) != 0u;
        if (weighted_views_only) {
          EXPECT_EQ(mask, 1u) << col << "," << row;
          const PlaneHypothesis h = PlaneAt(p, col, row);
          EXPECT_NEAR(StoredCost(p, col, row), test::ConventionalViewCost(p, 0, col, row, h), 1e-5f)
              << col << "," << row;
        }
      }
    }
    if (!weighted_views_only) {
      EXPECT_GT(redrawn, 0);
    }
  }
}

// The last selection holds only a view that matches nothing (the plane's
// negative): every scored view mismatches, view selection falls back to all
// views, and the pixel's next update scores all of them again.
TEST(UpdatePixel, WeightedViewsOnlyFallsBackToAllViewsWhenTheSelectionFails) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  test::AddSourceView(test::MirroredSourceCamera(), &s);
  for (float& v : s.src_images.back().data) v = 1.0f - v;
  s.params.weighted_views_only = 1;
  const PassParams& p = s.params;
  ScoreAll(p);
  for (uint32_t& m : s.state_mask) m = 2u;  // the negative view alone
  UpdatePixel(p, kCol, kRow, /*iteration=*/1);
  EXPECT_EQ(p.state.mask[p.state.Index(kCol, kRow)], 3u);
  UpdatePixel(p, kCol, kRow, /*iteration=*/2);
  EXPECT_EQ(p.state.mask[p.state.Index(kCol, kRow)], 1u);  // the matching view, found again
  EXPECT_NEAR(PlaneAt(p, kCol, kRow).depth, kDepth, 0.01f * kDepth);
}

// An unlit pixel (PassParams::unlit) holds no plane after initialisation or
// scoring, is not updated, and no neighbour takes a plane from it.
TEST(UpdatePixel, UnlitPixelHoldsNoPlaneAndIsNeverUpdated) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  PassParams& p = s.params;
  const std::vector<uint8_t> unlit = test::OnePixelMask(p, kCol, kRow);
  p.unlit = unlit.data();
  ASSERT_GT(PlaneAt(p, kCol, kRow).depth, 0.0f);  // scored before it was marked
  ScorePixel(p, kCol, kRow);
  EXPECT_EQ(PlaneAt(p, kCol, kRow).depth, 0.0f);
  EXPECT_EQ(StoredCost(p, kCol, kRow), kMaxCost);
  for (int iteration = 0; iteration < 3; ++iteration) UpdatePixel(p, kCol, kRow, iteration);
  EXPECT_EQ(PlaneAt(p, kCol, kRow).depth, 0.0f);
  InitializePixel(p, kCol, kRow);
  EXPECT_EQ(PlaneAt(p, kCol, kRow).depth, 0.0f);
  // A lit neighbour still finds the true plane around it.
  UpdatePixel(p, kCol + 1, kRow, 0);
  EXPECT_NEAR(PlaneAt(p, kCol + 1, kRow).depth, kDepth, 0.01f * kDepth);
}

// A held pixel (PassParams::held) keeps the plane it has, wrong or right:
// neither propagation nor refinement moves it, while its neighbours still
// take the true plane, its own included.
TEST(UpdatePixel, HeldPixelKeepsItsPlaneAndStillProposesIt) {
  test::PlaneScene s;
  MakeScoredScene(&s);
  PassParams& p = s.params;
  const std::vector<uint8_t> held = test::OnePixelMask(p, kCol, kRow);
  p.held = held.data();
  const PlaneHypothesis wrong{1.1f * kDepth, kFrontoParallel};
  p.state.Set(p.state.Index(kCol, kRow), wrong);
  ScorePixel(p, kCol, kRow);
  const float cost = StoredCost(p, kCol, kRow);
  for (int iteration = 0; iteration < 3; ++iteration) UpdatePixel(p, kCol, kRow, iteration);
  EXPECT_EQ(PlaneAt(p, kCol, kRow).depth, wrong.depth);
  EXPECT_EQ(StoredCost(p, kCol, kRow), cost);
  // Not held, the same pixel takes the true plane from its neighbours.
  p.held = nullptr;
  UpdatePixel(p, kCol, kRow, 0);
  EXPECT_NEAR(PlaneAt(p, kCol, kRow).depth, kDepth, 0.01f * kDepth);
}

}  // namespace
}  // namespace core
}  // namespace msp
