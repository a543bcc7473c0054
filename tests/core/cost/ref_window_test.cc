#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/cost/window_batch.h"
#include "core/cost/window_cost.h"
#include "core/math/rng.h"
#include "tests/support/images.h"

namespace msp {
namespace core {
namespace {

using test::Image;

constexpr int kW = 48, kH = 36;
const NccParams kUniform{5, 2, 0, 5.0f, 0.2f};

// The prepared reference values have zero mean and unit norm.
void ExpectNormalised(const RefWindow& w) {
  float sum = 0.0f, sum_sq = 0.0f;
  for (int k = 0; k < w.num_samples; ++k) {
    sum += w.value[k];
    sum_sq += w.value[k] * w.value[k];
  }
  EXPECT_NEAR(sum, 0.0f, 1e-5f);
  EXPECT_NEAR(sum_sq, 1.0f, 1e-5f);
}

TEST(RefWindow, PreparedWindowIsNormalised) {
  const Image img = test::NoiseImage(kW, kH, 3);
  RefWindow w;
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, nullptr, &w);
  ASSERT_EQ(w.num_samples, 36);
  EXPECT_EQ(w.textured, 1);
  ExpectNormalised(w);
  // Padding lanes up to 40 repeat the centre with no weight.
  for (int k = 36; k < 40; ++k) {
    EXPECT_EQ(w.x[k], 20.0f);
    EXPECT_EQ(w.y[k], 15.0f);
    EXPECT_EQ(w.value[k], 0.0f);
  }
}

TEST(RefWindow, BorderWindowKeepsTheSamplesInsideTheReference) {
  const Image img = test::NoiseImage(kW, kH, 3);
  RefWindow w;
  // Columns -2, 0, 2, 4, 6, 8: five of six inside; rows all inside.
  PrepareRefWindow(img.View(), 3, 15, 5, 2, 0, nullptr, &w);
  EXPECT_EQ(w.clipped, 1);
  ASSERT_EQ(w.num_samples, 30);
  for (int k = 0; k < w.num_samples; ++k) EXPECT_GE(w.x[k], 0.0f);
  // The corner: columns and rows 1, 3, 5 only; the centre (0, 0) is not a sample.
  PrepareRefWindow(img.View(), 0, 0, 5, 2, 0, nullptr, &w);
  EXPECT_EQ(w.num_samples, 9);
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, nullptr, &w);
  EXPECT_EQ(w.clipped, 0);
}

TEST(RefWindow, BilateralAndLargeWindowsTakeTheGeneralPath) {
  const Image img = test::NoiseImage(kW, kH, 3);
  RefWindow w;
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 1, nullptr, &w);
  EXPECT_EQ(w.num_samples, 0);
  PrepareRefWindow(img.View(), 20, 15, 5, 1, 0, nullptr, &w);  // 121 samples
  EXPECT_EQ(w.num_samples, 0);
  PrepareRefWindow(img.View(), 20, 15, 7, 2, 0, nullptr, &w);  // 8 x 8 = 64 still fits
  EXPECT_EQ(w.num_samples, 64);
}

// Regions: columns first..last are region 1, the others region 2, except
// that column `unlabelled` is 0.
std::vector<int32_t> StripeRegions(int first, int last, int unlabelled = -1) {
  std::vector<int32_t> regions(kW * kH);
  for (int row = 0; row < kH; ++row) {
    for (int col = 0; col < kW; ++col) {
      const bool stripe = col >= first && col <= last;
      regions[row * kW + col] = col == unlabelled ? 0 : (stripe ? 1 : 2);
    }
  }
  return regions;
}

TEST(RefWindow, RegionWindowKeepsItsCentresRegionAndTheUnlabelled) {
  const Image img = test::NoiseImage(kW, kH, 3);
  const std::vector<int32_t> regions = StripeRegions(0, 21, 15);
  RefWindow w;
  // Centre (20, 15): columns 15..25 step 2; 15 is unlabelled, 17-21 region
  // 1, 23 and 25 region 2: 4 of 6 columns remain.
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, regions.data(), &w);
  ASSERT_EQ(w.num_samples, 24);
  EXPECT_EQ(w.clipped, 1);  // partial: the centre's mapping is checked
  for (int k = 0; k < w.num_samples; ++k) EXPECT_LT(w.x[k], 22.0f);
  ExpectNormalised(w);
  // Whole windows: no regions, one region throughout, an unlabelled centre.
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, nullptr, &w);
  EXPECT_EQ(w.num_samples, 36);
  PrepareRefWindow(img.View(), 8, 15, 5, 2, 0, regions.data(), &w);
  EXPECT_EQ(w.num_samples, 36);
  EXPECT_EQ(w.clipped, 0);
  const std::vector<int32_t> centre_unlabelled = StripeRegions(0, 21, 20);
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, centre_unlabelled.data(), &w);
  EXPECT_EQ(w.num_samples, 36);
}

TEST(RefWindow, RegionSliverKeepsTheWholeWindow) {
  const Image img = test::NoiseImage(kW, kH, 3);
  // Centre (19, 15) in a stripe of columns 19-20: of the window's columns
  // 14, 16, ..., 24 only 20 is in it (one of six, under a quarter): too few
  // samples to match, the whole window stays.
  RefWindow w;
  PrepareRefWindow(img.View(), 19, 15, 5, 2, 0, StripeRegions(19, 20).data(), &w);
  EXPECT_EQ(w.num_samples, 36);
  // Columns 18-20: two of six (a third) are enough.
  PrepareRefWindow(img.View(), 19, 15, 5, 2, 0, StripeRegions(18, 20).data(), &w);
  EXPECT_EQ(w.num_samples, 12);
}

// A blank wall pixel beside a textured box: under the box's shift its whole
// window matches on the box's texture, so the box's depth would be the
// wall's. Cut to the wall's region the window holds no texture, and the
// shift costs kMaxCost: no evidence, which the wall's own plane then wins.
TEST(RefWindow, WindowCutAtTheRegionEdgeGivesTheBoxsDepthNoEvidence) {
  Image ref = test::NoiseImage(kW, kH, 21);
  for (int row = 0; row < kH; ++row) {
    for (int col = 24; col < kW; ++col) ref.At(col, row) = 0.5f;  // the wall
  }
  // The source sees the box 3 px further left; the wall is blank anyway.
  Image src = test::FlatImage(kW, kH, 0.5f);
  for (int row = 0; row < kH; ++row) {
    for (int col = 0; col + 3 < kW; ++col) src.At(col, row) = ref.At(col + 3, row);
  }
  const Mat3 box_shift{{1.0f, 0.0f, -3.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}};
  const std::vector<int32_t> regions = StripeRegions(0, 23);
  RefWindow whole, cut;
  PrepareRefWindow(ref.View(), 26, 15, 5, 2, 0, nullptr, &whole);
  PrepareRefWindow(ref.View(), 26, 15, 5, 2, 0, regions.data(), &cut);
  EXPECT_LT(WindowNccCost(whole, ref.View(), src.View(), box_shift, kUniform), 0.05f);
  EXPECT_EQ(cut.textured, 0);
  EXPECT_EQ(WindowNccCost(cut, ref.View(), src.View(), box_shift, kUniform), kMaxCost);
}

// True when a sample of w warps to within a rounding margin of the source
// border: the general and fast forms may then disagree on whether it counts.
bool OnTheBorder(const RefWindow& w, const Mat3& H) {
  constexpr float kMargin = 1e-3f;
  for (int k = 0; k < w.num_samples; ++k) {
    float u, v;
    if (!ApplyHomography(H, w.x[k], w.y[k], &u, &v)) continue;
    for (const float d : {u, v, u - (kW - 1.0f), v - (kH - 1.0f)}) {
      if (std::fabs(d) < kMargin) return true;
    }
  }
  return false;
}

TEST(RefWindow, CostEqualsTheGeneralNcc) {
  const Image ref = test::NoiseImage(kW, kH, 3);
  const Image src = test::NoiseImage(kW, kH, 4);
  const Image same = ref;
  int fast = 0, partial = 0;
  for (int row = 5; row < kH - 5; row += 3) {
    for (int col = 5; col < kW - 5; col += 3) {
      RefWindow w;
      PrepareRefWindow(ref.View(), col, row, 5, 2, 0, nullptr, &w);
      // The larger shifts push windows near the borders partly out of the source.
      for (const Mat3& H : {test::MildWarp(0.3f, -0.4f), test::MildWarp(1.7f, 0.6f),
                            test::MildWarp(-2.5f, 3.2f), test::MildWarp(-6.0f, 4.5f)}) {
        if (OnTheBorder(w, H)) continue;
        for (const Image* s : {&src, &same}) {
          const float general = GeneralNccCost(ref.View(), s->View(), H, col, row, kUniform);
          EXPECT_NEAR(WindowNccCost(w, ref.View(), s->View(), H, kUniform), general, 2e-4f)
              << col << "," << row;
          SourceSums sums;
          const bool whole = WholeWindowSums(w, s->View(), H, &sums);
          fast += whole;
          partial += !whole && general < kMaxCost;
        }
      }
    }
  }
  EXPECT_GT(fast, 100);    // most windows lay wholly inside the source
  EXPECT_GT(partial, 20);  // and partial windows were compared too
}

// Windows over the reference border, and the corner, whose centre lies
// outside its own samples: the same cost as GeneralNccCost, which skips the
// samples outside the reference.
TEST(RefWindow, BorderWindowCostEqualsTheGeneralNcc) {
  const Image ref = test::NoiseImage(kW, kH, 7);
  const Image src = test::NoiseImage(kW, kH, 8);
  const Image same = ref;
  int compared = 0, centre_out = 0;
  for (int row = 0; row < kH; ++row) {
    for (int col = 0; col < kW; ++col) {
      if (col >= 5 && row >= 5 && col < kW - 5 && row < kH - 5) continue;
      RefWindow w;
      PrepareRefWindow(ref.View(), col, row, 5, 2, 0, nullptr, &w);
      ASSERT_EQ(w.clipped, 1);
      for (const Mat3& H :
           {test::MildWarp(0.3f, -0.4f), test::MildWarp(-0.6f, 0.7f), test::MildWarp(1.7f, 0.6f)}) {
        if (OnTheBorder(w, H)) continue;
        for (const Image* s : {&src, &same}) {
          const float general = GeneralNccCost(ref.View(), s->View(), H, col, row, kUniform);
          EXPECT_NEAR(WindowNccCost(w, ref.View(), s->View(), H, kUniform), general, 2e-4f)
              << col << "," << row;
          ++compared;
          centre_out += !CentreInSource(H, s->View(), col, row);
        }
      }
    }
  }
  EXPECT_GT(compared, 500);
  EXPECT_GT(centre_out, 10);  // windows whose centre leaves the source were among them
  // The corner window's samples (1, 3, 5) all land inside the source, its
  // centre does not: the view does not see the pixel. (The vector path's
  // padding lanes repeat the centre and would catch it; the scalar path
  // has no padding.)
  RefWindow corner;
  PrepareRefWindow(ref.View(), 0, 0, 5, 2, 0, nullptr, &corner);
  const Mat3 half_left_up = {{1, 0, -0.5f, 0, 1, -0.5f, 0, 0, 1}};
  SourceSums sums;
  ASSERT_TRUE(WholeWindowSumsScalar(corner, src.View(), half_left_up, &sums));
  EXPECT_EQ(GeneralNccCost(ref.View(), src.View(), half_left_up, 0, 0, kUniform), kMaxCost);
  EXPECT_EQ(WindowNccCost(corner, ref.View(), src.View(), half_left_up, kUniform), kMaxCost);
}

// The batch's costs of the window at (col, row) under the warps H in
// `lanes`, and each warp's cost alone (kMaxCost outside `lanes`).
void BatchAndAlone(const Image& ref, const Image& src, const Mat3* H, uint32_t lanes, int col,
                   int row, RefWindow* w, float* batch, float* alone) {
  PrepareRefWindow(ref.View(), col, row, 5, 2, 0, nullptr, w);
  WindowNccCosts(*w, ref.View(), src.View(), H, lanes, kUniform, batch);
  for (int l = 0; l < kWindowLanes; ++l) {
    alone[l] =
        ((lanes >> l) & 1u) ? WindowNccCost(*w, ref.View(), src.View(), H[l], kUniform) : kMaxCost;
  }
}

// Eight warps at once, lane by lane the same cost as WindowNccCost alone:
// windows inside the source, leaving it in part, leaving it whole, over the
// reference border, and a lane left unused.
TEST(RefWindow, BatchOfWarpsCostsWhatEachWarpCostsAlone) {
  const Image ref = test::NoiseImage(kW, kH, 11);
  const Image src = test::NoiseImage(kW, kH, 12);
  const Mat3 H[kWindowLanes] = {test::MildWarp(0.3f, -0.4f), test::MildWarp(-0.6f, 0.7f),
                                test::MildWarp(1.7f, 0.6f),  test::MildWarp(9.5f, 0.2f),
                                test::MildWarp(-8.0f, 3.0f), test::MildWarp(60.0f, 0.0f),
                                test::MildWarp(2.2f, -7.5f), test::MildWarp(0.0f, 0.0f)};
  const uint32_t lanes = 0x7fu;  // lane 7 unused
  int compared = 0, partial = 0, clipped = 0;
  for (int row = 0; row < kH; ++row) {
    for (int col = 0; col < kW; ++col) {
      RefWindow w;
      float costs[kWindowLanes], alone[kWindowLanes];
      BatchAndAlone(ref, src, H, lanes, col, row, &w, costs, alone);
      for (int l = 0; l < 7; ++l) {
        EXPECT_NEAR(costs[l], alone[l], 2e-4f) << col << "," << row << " lane " << l;
        SourceSums sums;
        partial += !WholeWindowSumsScalar(w, src.View(), H[l], &sums) &&
                   CentreInSource(H[l], src.View(), col, row) && costs[l] < kMaxCost;
        ++compared;
      }
      clipped += w.clipped;
      EXPECT_EQ(costs[7], kMaxCost);
    }
  }
  EXPECT_EQ(compared, 7 * kW * kH);
  EXPECT_GT(partial, 500);  // partial windows with a cost were among them
  EXPECT_GT(clipped, 500);
  // An untextured reference window costs kMaxCost in every lane.
  const Image flat = test::FlatImage(kW, kH, 0.5f);
  RefWindow w;
  PrepareRefWindow(flat.View(), 20, 15, 5, 2, 0, nullptr, &w);
  float costs[kWindowLanes];
  WindowNccCosts(w, flat.View(), src.View(), H, lanes, kUniform, costs);
  for (int l = 0; l < kWindowLanes; ++l) EXPECT_EQ(costs[l], kMaxCost);
}

// Lanes whose warps all keep the window inside the source (the batch's
// shortcut), and such warps among others, cost what each costs alone.
TEST(RefWindow, BatchOfWholeWarpsCostsWhatEachWarpCostsAlone) {
  const Image ref = test::NoiseImage(kW, kH, 13);
  const Image src = test::NoiseImage(kW, kH, 14);
  Mat3 H[kWindowLanes];
  for (int l = 0; l < kWindowLanes; ++l) H[l] = test::MildWarp(0.37f * l - 1.2f, 0.9f - 0.23f * l);
  for (const uint32_t lanes : {0xffu, 0x5au, 0x80u}) {
    for (int row = 0; row < kH; ++row) {
      for (int col = 0; col < kW; ++col) {
        RefWindow w;
        float costs[kWindowLanes], alone[kWindowLanes];
        BatchAndAlone(ref, src, H, lanes, col, row, &w, costs, alone);
        for (int l = 0; l < kWindowLanes; ++l) {
          EXPECT_NEAR(costs[l], alone[l], 2e-4f) << col << "," << row << " lane " << l;
        }
      }
    }
  }
}

TEST(RefWindow, BoxHoldsTheSamplesAndTheCentre) {
  const Image img = test::NoiseImage(kW, kH, 3);
  RefWindow w;
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, nullptr, &w);
  EXPECT_EQ(w.box[0], 15.0f);
  EXPECT_EQ(w.box[1], 25.0f);
  EXPECT_EQ(w.box[2], 10.0f);
  EXPECT_EQ(w.box[3], 20.0f);
  // The corner window's samples are columns and rows 1, 3, 5; its centre is (0, 0).
  PrepareRefWindow(img.View(), 0, 0, 5, 2, 0, nullptr, &w);
  EXPECT_EQ(w.box[0], 0.0f);
  EXPECT_EQ(w.box[1], 5.0f);
  EXPECT_EQ(w.box[2], 0.0f);
  EXPECT_EQ(w.box[3], 5.0f);
}

#if defined(MSP_WINDOW_SUMS_AVX2)
// WholeBoxLanes vouches for a lane only when every position of the box has
// its support in the source, and does vouch for boxes well inside.
TEST(RefWindow, WholeBoxLanesVouchOnlyForBoxesInside) {
  const ImageView src{nullptr, kW, kH, kW};
  int vouched = 0, refused = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Mat3 H[kWindowLanes];
    for (int l = 0; l < kWindowLanes; ++l) {
      const uint64_t key = Mix64(1000u + trial * kWindowLanes + l);
      const float shift_x = 50.0f * RandomUniform(key, 0) - 25.0f;
      const float shift_y = 40.0f * RandomUniform(key, 1) - 20.0f;
      H[l] = test::MildWarp(shift_x, shift_y);
      H[l].m[6] = 0.04f * RandomUniform(key, 2) - 0.02f;  // strongly projective, at times behind
      H[l].m[7] = 0.04f * RandomUniform(key, 3) - 0.02f;
    }
    const WarpLanes warp = WarpPerLane(H, 0xffu, src);
    const float x0 = 3.0f + trial % 20, y0 = 2.0f + trial % 15;
    const uint32_t whole = WholeBoxLanes(warp, x0, x0 + 10.0f, y0, y0 + 10.0f);
    uint32_t inside = 0xffu;
    for (float y = y0; y <= y0 + 10.0f; y += 0.5f) {
      for (float x = x0; x <= x0 + 10.0f; x += 0.5f) {
        const WarpedCells c = WarpCells(warp, _mm256_set1_ps(x), _mm256_set1_ps(y));
        inside &= static_cast<uint32_t>(_mm256_movemask_ps(c.inside));
      }
    }
    EXPECT_EQ(whole & ~inside, 0u) << "trial " << trial;
    vouched += __builtin_popcount(whole);
    refused += __builtin_popcount(inside & ~whole);
  }
  EXPECT_GT(vouched, 400);
  EXPECT_LT(refused, vouched / 10);  // only boxes within the margin of the bounds
}

// CentreNearSourceLanes drops only lanes that WindowNccCost prices at
// kMaxCost: their centre fails CentreInSource, and their window (unless
// clipped) is not whole.
TEST(RefWindow, CentreTestDropsOnlyLanesThatCostMax) {
  const Image ref = test::NoiseImage(kW, kH, 15);
  const Image src = test::NoiseImage(kW, kH, 16);
  int dropped = 0, kept = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Mat3 H[kWindowLanes];
    for (int l = 0; l < kWindowLanes; ++l) {
      const uint64_t key = Mix64(5000u + trial * kWindowLanes + l);
      H[l] = test::MildWarp(70.0f * RandomUniform(key, 0) - 35.0f,
                            56.0f * RandomUniform(key, 1) - 28.0f);
      H[l].m[6] = 0.04f * RandomUniform(key, 2) - 0.02f;  // strongly projective, at times behind
      H[l].m[7] = 0.04f * RandomUniform(key, 3) - 0.02f;
    }
    const int col = trial % kW, row = (7 * trial) % kH;
    RefWindow w;
    PrepareRefWindow(ref.View(), col, row, 5, 2, 0, nullptr, &w);
    const uint32_t near = CentreNearSourceLanes(WarpPerLane(H, 0xffu, src.View()), col, row);
    for (int l = 0; l < kWindowLanes; ++l) {
      if ((near >> l) & 1u) {
        ++kept;
        continue;
      }
      ++dropped;
      SourceSums sums;
      EXPECT_FALSE(CentreInSource(H[l], src.View(), col, row))
          << "trial " << trial << " lane " << l;
      // (A window clipped by the reference border may not hold its centre.)
      if (!w.clipped) {
        EXPECT_FALSE(WholeWindowSumsScalar(w, src.View(), H[l], &sums)) << "lane " << l;
      }
      EXPECT_EQ(WindowNccCost(w, ref.View(), src.View(), H[l], kUniform), kMaxCost);
    }
  }
  EXPECT_GT(dropped, 300);
  EXPECT_GT(kept, 300);
}
#endif

TEST(RefWindow, PartialWindowNeedsItsCentreAndHalfTheSamples) {
  const Image img = test::NoiseImage(kW, kH, 3);
  RefWindow w;
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, nullptr, &w);
  // Samples land at x = 42..52: the three columns past x = 47 leave the
  // source, half the window stays, and so does the centre (x = 47).
  const Mat3 right_third_out = {{1, 0, 27.0f, 0, 1, 0, 0, 0, 1}};
  EXPECT_LT(WindowNccCost(w, img.View(), img.View(), right_third_out, kUniform), kMaxCost);
  EXPECT_NEAR(WindowNccCost(w, img.View(), img.View(), right_third_out, kUniform),
              GeneralNccCost(img.View(), img.View(), right_third_out, 20, 15, kUniform), 2e-4f);
  const Mat3 centre_out = {{1, 0, 28.0f, 0, 1, 0, 0, 0, 1}};  // centre at x = 48
  EXPECT_EQ(WindowNccCost(w, img.View(), img.View(), centre_out, kUniform), kMaxCost);
}

TEST(RefWindow, ScalarAndVectorSumsAgree) {
  const Image ref = test::NoiseImage(kW, kH, 5);
  const Image src = test::NoiseImage(kW, kH, 6);
  RefWindow w;
  PrepareRefWindow(ref.View(), 24, 18, 5, 2, 0, nullptr, &w);
  SourceSums scalar, vector;
  ASSERT_TRUE(WholeWindowSumsScalar(w, src.View(), test::MildWarp(0.3f, 0.2f), &scalar));
  ASSERT_TRUE(WholeWindowSums(w, src.View(), test::MildWarp(0.3f, 0.2f), &vector));
  EXPECT_NEAR(scalar.s, vector.s, 1e-4f);
  EXPECT_NEAR(scalar.ss, vector.ss, 1e-4f);
  EXPECT_NEAR(scalar.rs, vector.rs, 1e-5f);
}

TEST(RefWindow, SampleOutsideTheSourceRefusesTheFastPath) {
  const Image img = test::NoiseImage(kW, kH, 3);
  RefWindow w;
  PrepareRefWindow(img.View(), 20, 15, 5, 2, 0, nullptr, &w);
  SourceSums sums;
  const Mat3 near_right_edge = {
      {1, 0, kW - 1.0f - 25.5f, 0, 1, 0, 0, 0, 1}};  // last column at 46.5
  EXPECT_TRUE(WholeWindowSumsScalar(w, img.View(), near_right_edge, &sums));
  const Mat3 on_right_edge = {{1, 0, kW - 1.0f - 25.0f, 0, 1, 0, 0, 0, 1}};  // last column at 47
  EXPECT_FALSE(WholeWindowSumsScalar(w, img.View(), on_right_edge, &sums));
  EXPECT_FALSE(WholeWindowSums(w, img.View(), on_right_edge, &sums));
  const Mat3 behind = {{1, 0, 0, 0, 1, 0, 0, 0, -1}};
  EXPECT_FALSE(WholeWindowSums(w, img.View(), behind, &sums));
}

TEST(RefWindow, FlatReferenceCostsMax) {
  const Image flat = test::FlatImage(kW, kH, 0.5f);
  const Image src = test::NoiseImage(kW, kH, 4);
  RefWindow w;
  PrepareRefWindow(flat.View(), 20, 15, 5, 2, 0, nullptr, &w);
  EXPECT_EQ(w.textured, 0);
  EXPECT_EQ(WindowNccCost(w, flat.View(), src.View(), test::MildWarp(0.3f, 0.2f), kUniform),
            kMaxCost);
}

}  // namespace
}  // namespace core
}  // namespace msp
