#include "core/deformable/deformable_cost.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/support/deformable_costs.h"
#include "tests/support/plane_scene.h"

namespace msp {
namespace core {
namespace {

constexpr int kCol = 100, kRow = 75;
const Vec3 kFrontoParallel{0.0f, 0.0f, -1.0f};

AnchorSet AnchorsAt(const int (*offsets)[2], int count, int col, int row) {
  AnchorSet a{};
  a.count = count;
  for (int k = 0; k < count; ++k) {
    a.cols[k] = col + offsets[k][0];
    a.rows[k] = row + offsets[k][1];
  }
  return a;
}

// One anchor per sector, 20 px from p.
AnchorSet RingOfAnchors() {
  const int ring[kMaxAnchors][2] = {{20, 0},  {14, 14},   {0, 20},  {-14, 14},
                                    {-20, 0}, {-14, -14}, {0, -20}, {14, -14}};
  return AnchorsAt(ring, kMaxAnchors, kCol, kRow);
}

// Anchor windows sum their samples in another order than the centre window
// (or take the general form), so equal windows agree to float rounding.
constexpr float kRounding = 1e-5f;

// Anchor windows equal to the centre window.
DeformableParams SameWindow(const PassParams& p) {
  DeformableParams d = DefaultDeformableParams();
  d.anchor_window_radius = p.ncc.window_radius;
  d.anchor_window_step = p.ncc.window_step;
  return d;
}

TEST(DeformableCost, AnchorsAtTheCentreGiveTheConventionalCost) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  const int zero[kMaxAnchors][2] = {};
  const AnchorSet a = AnchorsAt(zero, kMaxAnchors, kCol, kRow);
  for (float depth : {4.0f, 4.1f, 3.5f}) {  // a good and two wrong hypotheses
    const PlaneHypothesis h{depth, kFrontoParallel};
    EXPECT_NEAR(test::DeformableViewCost(s.params, 0, kCol, kRow, h, a, SameWindow(s.params)),
                test::ConventionalViewCost(s.params, 0, kCol, kRow, h), kRounding);
  }
}

TEST(DeformableCost, NoAnchorsIsExactlyTheConventionalCost) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  AnchorSet none{};
  const PlaneHypothesis h{4.2f, kFrontoParallel};
  EXPECT_EQ(test::DeformableViewCost(s.params, 0, kCol, kRow, h, none, DefaultDeformableParams()),
            test::ConventionalViewCost(s.params, 0, kCol, kRow, h));
}

TEST(DeformableCost, GeometricTermAsInTheConventionalCost) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  // A source depth map without depth: the geometric term is its maximum.
  const std::vector<float> empty(s.src.width * s.src.height, 0.0f);
  s.params.src[0].depth = ImageView{empty.data(), s.src.width, s.src.height, s.src.width};
  s.params.geometric = 1;
  const int zero[kMaxAnchors][2] = {};
  const AnchorSet a = AnchorsAt(zero, kMaxAnchors, kCol, kRow);
  const PlaneHypothesis h{4.0f, kFrontoParallel};
  const float conventional = test::ConventionalViewCost(s.params, 0, kCol, kRow, h);
  EXPECT_NEAR(test::DeformableViewCost(s.params, 0, kCol, kRow, h, a, SameWindow(s.params)),
              conventional, kRounding);
  s.params.geometric = 0;
  EXPECT_NEAR(conventional - test::ConventionalViewCost(s.params, 0, kCol, kRow, h),
              s.params.geom_lambda * s.params.geom_max_error, 1e-5f);
}

TEST(DeformableCost, SpreadAnchorsMatchTheTruePlaneOnly) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  const AnchorSet a = RingOfAnchors();
  const DeformableParams d = DefaultDeformableParams();
  const PlaneHypothesis truth{4.0f, kFrontoParallel};
  const PlaneHypothesis wrong{4.4f, kFrontoParallel};
  EXPECT_LT(test::DeformableViewCost(s.params, 0, kCol, kRow, truth, a, d), 0.05f);
  EXPECT_GT(test::DeformableViewCost(s.params, 0, kCol, kRow, wrong, a, d), 0.5f);
  // All views at once, weights skip a view.
  float costs[kMaxSourceViews], conventional[kMaxSourceViews];
  const float weights[1] = {1.0f};
  DeformableWindows windows;
  PrepareDeformableWindows(s.params, kCol, kRow, a, d, &windows);
  test::DeformableViewCosts(s.params, windows, truth, d, weights, costs, conventional);
  EXPECT_EQ(costs[0], test::DeformableViewCost(s.params, 0, kCol, kRow, truth, a, d));
  // The conventional cost comes out on the way, equal to ViewCosts'.
  EXPECT_EQ(conventional[0], test::ConventionalViewCost(s.params, 0, kCol, kRow, truth));
  const float skip[1] = {0.0f};
  test::DeformableViewCosts(s.params, windows, truth, d, skip, costs, conventional);
  EXPECT_EQ(costs[0], kMaxCost);
  EXPECT_EQ(conventional[0], kMaxCost);
}

// The bounded aggregate: exact (with the conventional aggregate) when the
// limit is above it, otherwise a figure between the limit and the exact
// cost; two views so that a sum can stop half way.
TEST(DeformableCost, BoundedAggregateStopsOnlyAtItsLimit) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  s.params.src[1] = s.params.src[0];
  s.params.num_src = 2;
  const DeformableParams d = DefaultDeformableParams();
  const float weights[2] = {1.0f, 0.5f};
  int stopped = 0;
  for (int row = 30; row < s.ref.height - 30; row += 11) {
    for (int col = 30; col < s.ref.width - 30; col += 13) {
      const int ring[4][2] = {{12, 0}, {0, 12}, {-12, 0}, {0, -12}};
      DeformableWindows w;
      PrepareDeformableWindows(s.params, col, row, AnchorsAt(ring, 4, col, row), d, &w);
      for (float off : {1.0f, 1.05f, 1.2f}) {
        const PlaneHypothesis h{4.0f * off, kFrontoParallel};
        float costs[kMaxSourceViews], conventional[kMaxSourceViews];
        test::DeformableViewCosts(s.params, w, h, d, weights, costs, conventional);
        const float exact = AggregateCost(costs, weights, 2);
        float conventional_cost = -1.0f;
        ASSERT_NEAR(
            DeformableAggregateBelow(s.params, w, h, d, weights, exact + 0.01f, &conventional_cost),
            exact, 1e-6f);
        EXPECT_NEAR(conventional_cost, AggregateCost(conventional, weights, 2), 1e-6f);
        const float limit = 0.6f * exact;
        const float bounded =
            DeformableAggregateBelow(s.params, w, h, d, weights, limit, &conventional_cost);
        ASSERT_GE(bounded, limit) << col << "," << row;
        ASSERT_LE(bounded, exact + 1e-6f) << col << "," << row;
        stopped += bounded < exact - 1e-6f;
      }
    }
  }
  EXPECT_GT(stopped, 20);  // the first view alone often sufficed
}

// The anchors' candidates scored together (one vector lane each) cost, row
// by row, what DeformableViewCosts gives each alone; a row without a
// candidate costs kMaxCost.
TEST(DeformableCost, CandidateRowsCostWhatEachCandidateCostsAlone) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  const AnchorSet a = RingOfAnchors();
  const DeformableParams d = DefaultDeformableParams();
  DeformableWindows windows;
  PrepareDeformableWindows(s.params, kCol, kRow, a, d, &windows);
  PlaneHypothesis h[kMaxAnchors];
  bool has[kMaxAnchors];
  for (int k = 0; k < kMaxAnchors; ++k) {
    h[k] = PlaneHypothesis{3.7f + 0.1f * k, Normalized(Vec3{0.05f * (k - 4), 0.02f * k, -1.0f})};
    has[k] = k != 5;
  }
  h[3] = PlaneHypothesis{4.0f, kFrontoParallel};  // the truth
  float costs[kMaxAnchors * kMaxSourceViews], conventional[kMaxAnchors * kMaxSourceViews];
  test::DeformableCandidateViewCosts(s.params, windows, h, has, kMaxAnchors, d, costs,
                                     conventional);
  for (int k = 0; k < kMaxAnchors; ++k) {
    float alone[kMaxSourceViews], alone_conventional[kMaxSourceViews];
    test::DeformableViewCosts(s.params, windows, h[k], d, nullptr, alone, alone_conventional);
    for (int j = 0; j < s.params.num_src; ++j) {
      const int i = k * kMaxSourceViews + j;
      if (!has[k]) {
        EXPECT_EQ(costs[i], kMaxCost);
        EXPECT_EQ(conventional[i], kMaxCost);
        continue;
      }
      EXPECT_NEAR(costs[i], alone[j], 1e-4f) << k << " " << j;
      EXPECT_NEAR(conventional[i], alone_conventional[j], 1e-4f) << k << " " << j;
    }
  }
  EXPECT_LT(costs[3 * kMaxSourceViews], 0.05f);
  EXPECT_GT(costs[0], 0.3f);  // depth 3.7, tilted
}

TEST(DeformableCost, TexturedAnchorsRescueATexturelessCentre) {
  // The reference is flat inside a disk of radius 12 around p: the centre
  // window alone has no signal (cost 2), the anchors outside still match.
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  for (int r = kRow - 12; r <= kRow + 12; ++r) {
    for (int c = kCol - 12; c <= kCol + 12; ++c) {
      if ((c - kCol) * (c - kCol) + (r - kRow) * (r - kRow) <= 144) {
        s.ref_image.At(c, r) = 0.5f;
      }
    }
  }
  const AnchorSet a = RingOfAnchors();
  const PlaneHypothesis truth{4.0f, kFrontoParallel};
  const PlaneHypothesis wrong{4.4f, kFrontoParallel};
  EXPECT_EQ(test::ConventionalViewCost(s.params, 0, kCol, kRow, truth), kMaxCost);
  const DeformableParams d = DefaultDeformableParams();
  const float good = test::DeformableViewCost(s.params, 0, kCol, kRow, truth, a, d);
  EXPECT_NEAR(good, d.lambda * kMaxCost, 0.05f);  // only the centre term is lost
  EXPECT_GT(test::DeformableViewCost(s.params, 0, kCol, kRow, wrong, a, d), good + 0.3f);
}

TEST(DeformableCost, AViewThatDoesNotSeeThePixelCostsTheMaximum) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  const PlaneHypothesis truth{4.0f, kFrontoParallel};
  const Mat3 H = WarpHomography(s.params.src[0].rel, PreparePlane(s.params, 0, 0, truth).warp);
  const ImageView& src = s.params.src[0].image;
  // The edge of the source's view on row kRow: a pixel 3 columns outside it,
  // anchors 26 columns further in, inside it.
  int edge = -1;
  for (int c = 6; c + 1 < s.ref.width - 6 && edge < 0; ++c) {
    if (CentreInSource(H, src, c, kRow) != CentreInSource(H, src, c + 1, kRow)) edge = c;
  }
  ASSERT_GE(edge, 0) << "the source sees the whole row";
  const int side = CentreInSource(H, src, edge + 1, kRow) ? 1 : -1;
  const int col = side > 0 ? edge - 2 : edge + 3;
  ASSERT_FALSE(CentreInSource(H, src, col, kRow));
  int offsets[kMaxAnchors][2];
  for (int k = 0; k < kMaxAnchors; ++k) {
    offsets[k][0] = side * 26;
    offsets[k][1] = 3 * k - 12;
  }
  const AnchorSet a = AnchorsAt(offsets, kMaxAnchors, col, kRow);
  const DeformableParams d = DefaultDeformableParams();
  EXPECT_EQ(test::DeformableViewCost(s.params, 0, col, kRow, truth, a, d), kMaxCost);
  // The same anchors around a pixel the view does see match the true plane.
  const int seen_col = col + side * 14;
  const AnchorSet seen = AnchorsAt(offsets, kMaxAnchors, seen_col, kRow);
  ASSERT_TRUE(CentreInSource(H, src, seen_col, kRow));
  EXPECT_LT(test::DeformableViewCost(s.params, 0, seen_col, kRow, truth, seen, d), 0.5f);
}

}  // namespace
}  // namespace core
}  // namespace msp
