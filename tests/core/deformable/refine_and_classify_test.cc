#include "core/deformable/refine_and_classify.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <vector>

#include "tests/support/plane_scene.h"

namespace msp {
namespace core {
namespace {

// The scene in a geometric pass: the source's depth map is the truth.
void MakeGeometricScene(test::PlaneScene* s, std::vector<float>* src_depth) {
  test::MakeScene(4.0f, true, s);
  *src_depth = test::PlaneDepthMap(s->src, s->depth);
  s->params.geometric = 1;
  s->params.src[0].depth = ImageView{src_depth->data(), s->src.width, s->src.height, s->src.width};
}

// Off the true depth by up to 9 % (a few pixels of disparity), pixel by
// pixel, so the refinement has somewhere to go.
void PerturbDepths(test::PlaneScene* s) {
  for (size_t i = 0; i < s->state_depth.size(); ++i) {
    s->state_depth[i] *= 1.0f + 0.03f * static_cast<float>(static_cast<int>(i * 37 % 7) - 3);
  }
}

// LocalRefineAndClassifyPixel on every pixel of a grid against
// LocalRefinePixel followed by ClassifyPixel on a copy of the state.
void ExpectSameAsSeparateSteps(test::PlaneScene* s, int pass, int* num_moved) {
  const ReliabilityParams rp = DefaultReliabilityParams(pass);
  const test::PlaneScene before = *s;
  std::vector<float> depth = s->state_depth, normal = s->state_normal, cost = s->state_cost;
  std::vector<uint32_t> mask = s->state_mask;
  PassParams separate = s->params;
  separate.state = PixelStateView{depth.data(), normal.data(), cost.data(),
                                  mask.data(),  s->ref.width,  s->ref.height};
  for (int row = 0; row < s->ref.height; row += 7) {
    for (int col = 0; col < s->ref.width; col += 5) {
      LocalRefinePixel(separate, col, row);
      const uint8_t expected = ClassifyPixel(separate, col, row, rp);
      const uint8_t fused = LocalRefineAndClassifyPixel(s->params, col, row, rp);
      const int i = s->params.state.Index(col, row);
      ASSERT_EQ(fused, expected) << col << "," << row;
      ASSERT_NEAR(s->state_depth[i], depth[i], 1e-5f * depth[i]) << col << "," << row;
      ASSERT_NEAR(s->state_cost[i], cost[i], 1e-5f) << col << "," << row;
      *num_moved += s->state_depth[i] != before.state_depth[i];
    }
  }
}

TEST(RefineAndClassify, PhotometricMatchesTheSeparateSteps) {
  for (bool textured : {true, false}) {
    test::PlaneScene s;
    test::MakeScene(4.0f, textured, &s);
    PerturbDepths(&s);
    int moved = 0;
    ExpectSameAsSeparateSteps(&s, 0, &moved);
    if (textured) {
      EXPECT_GT(moved, 100);  // the refinement did move depths
    }
  }
}

TEST(RefineAndClassify, GeometricMatchesTheSeparateSteps) {
  test::PlaneScene s;
  std::vector<float> src_depth;
  MakeGeometricScene(&s, &src_depth);
  PerturbDepths(&s);
  int moved = 0;
  ExpectSameAsSeparateSteps(&s, 2, &moved);
  EXPECT_GT(moved, 100);
}

// Fronto-parallel hypotheses at depth offsets `offs` over a grid of pixels,
// scored in two views (so that a sum can stop half way): check(w, h,
// weights, exact cost) for each.
template <typename Check>
void ForGridHypotheses(test::PlaneScene* s, std::initializer_list<float> offs, Check check) {
  s->params.src[1] = s->params.src[0];
  s->params.num_src = 2;
  const float weights[kMaxSourceViews] = {1.0f, 0.5f};
  for (int row = 10; row < s->ref.height - 10; row += 9) {
    for (int col = 10; col < s->ref.width - 10; col += 7) {
      RefWindow w;
      PrepareWindow(s->params, col, row, &w);
      for (float off : offs) {
        const PlaneHypothesis h{s->depth * off, Vec3{0.0f, 0.0f, -1.0f}};
        float costs[kMaxSourceViews];
        ViewCosts(s->params, w, h, weights, costs);
        check(w, h, weights, AggregateCost(costs, weights, 2));
      }
    }
  }
}

// The local refinement's candidate costs (AggregateViewCostBelow): exact
// without a limit, and under a limit either exact or a partial figure
// between the limit and the exact cost.
TEST(RefineAndClassify, BoundedCostStopsOnlyAtItsLimit) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  int stopped = 0;
  ForGridHypotheses(
      &s, {1.0f, 1.03f, 1.09f},
      [&](const RefWindow& w, const PlaneHypothesis& h, const float* weights, float exact) {
        const PassParams& p = s.params;
        ASSERT_NEAR(AggregateViewCostBelow(p, w, h, weights, kUnboundedCost), exact, 1e-6f);
        ASSERT_NEAR(AggregateViewCostBelow(p, w, h, weights, exact + 0.01f), exact, 1e-6f);
        const float limit = 0.6f * exact;
        const float bounded = AggregateViewCostBelow(p, w, h, weights, limit);
        ASSERT_GE(bounded, limit) << w.col << "," << w.row;
        ASSERT_LE(bounded, exact + 1e-6f) << w.col << "," << w.row;
        stopped += bounded < exact - 1e-6f;
      });
  EXPECT_GT(stopped, 100);  // the first view alone often sufficed
}

// In a geometric pass the geometric terms of all the views bound the cost
// from below before any window is scored: a hypothesis whose mean geometric
// term reaches the limit stops at that figure, and one below the limit
// still gets its exact cost.
TEST(RefineAndClassify, GeometricTermsBoundTheCostFirst) {
  test::PlaneScene s;
  std::vector<float> src_depth;
  MakeGeometricScene(&s, &src_depth);
  int bounded_by_geometry = 0;
  ForGridHypotheses(
      &s, {1.0f, 1.02f, 1.1f},
      [&](const RefWindow& w, const PlaneHypothesis& h, const float* weights, float exact) {
        const PassParams& p = s.params;
        const float geometric = MeanGeometricTerm(p, w.col, w.row, h, weights);
        ASSERT_NEAR(AggregateViewCostBelow(p, w, h, weights, exact + 0.01f), exact, 1e-6f);
        if (geometric > 0.0f) {
          ASSERT_NEAR(AggregateViewCostBelow(p, w, h, weights, geometric), geometric, 1e-6f);
          bounded_by_geometry += geometric < exact - 1e-3f;
        }
      });
  EXPECT_GT(bounded_by_geometry, 100);  // the windows' costs were never needed
}

TEST(RefineAndClassify, UnknownPixelsAreRefinedAsUsual) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  PerturbDepths(&s);
  // Without a selected view the refinement uses every view and the class is unknown.
  for (size_t i = 0; i < s.state_mask.size(); i += 3) s.state_mask[i] = 0u;
  int moved = 0;
  ExpectSameAsSeparateSteps(&s, 1, &moved);
  EXPECT_GT(moved, 100);
  const int i = s.params.state.Index(99, 75);
  ASSERT_EQ(s.state_mask[i], 0u);
  EXPECT_EQ(LocalRefineAndClassifyPixel(s.params, 99, 75, DefaultReliabilityParams(1)), kUnknown);
  EXPECT_EQ(LocalRefineAndClassifyPixel(s.params, 2, 75, DefaultReliabilityParams(1)), kUnknown);
}

}  // namespace
}  // namespace core
}  // namespace msp
