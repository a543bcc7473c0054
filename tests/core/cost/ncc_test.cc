#include "core/cost/ncc.h"

#include <gtest/gtest.h>

#include "tests/support/cameras.h"
#include "tests/support/images.h"

namespace msp {
namespace core {
namespace {

using test::Image;

constexpr int kW = 40, kH = 30;
const Mat3 kIdentity = test::Identity();
constexpr uint64_t kSeed = 99;

const NccParams kUniform{5, 2, 0, 5.0f, 0.2f};
const NccParams kBilateral{5, 1, 1, 5.0f, 0.2f};

TEST(Ncc, PatchAgainstItselfCostsZero) {
  const Image img = test::NoiseImage(kW, kH, kSeed);
  EXPECT_NEAR(GeneralNccCost(img.View(), img.View(), kIdentity, 20, 15, kUniform), 0.0f, 1e-5f);
  EXPECT_NEAR(GeneralNccCost(img.View(), img.View(), kIdentity, 20, 15, kBilateral), 0.0f, 1e-5f);
  // Near the border only the samples inside the reference count.
  EXPECT_NEAR(GeneralNccCost(img.View(), img.View(), kIdentity, 1, 2, kUniform), 0.0f, 1e-5f);
}

TEST(Ncc, InvariantToGainAndOffset) {
  const Image a = test::NoiseImage(kW, kH, kSeed);
  const Image b = test::NoiseImage(kW, kH, kSeed, 0.4f, 0.3f);
  EXPECT_NEAR(GeneralNccCost(a.View(), b.View(), kIdentity, 20, 15, kUniform), 0.0f, 1e-4f);
}

TEST(Ncc, NegatedPatchCostsTwo) {
  const Image a = test::NoiseImage(kW, kH, kSeed);
  const Image b = test::NoiseImage(kW, kH, kSeed, -1.0f, 1.0f);
  EXPECT_NEAR(GeneralNccCost(a.View(), b.View(), kIdentity, 20, 15, kUniform), 2.0f, 1e-4f);
}

TEST(Ncc, TexturelessOrOutsideIsMaxCost) {
  const Image a = test::NoiseImage(kW, kH, kSeed);
  const Image flat = test::FlatImage(kW, kH, 0.5f);
  EXPECT_EQ(GeneralNccCost(a.View(), flat.View(), kIdentity, 20, 15, kUniform), kMaxCost);
  const Mat3 shift = {{1, 0, 100, 0, 1, 0, 0, 0, 1}};  // centre lands outside the source
  EXPECT_EQ(GeneralNccCost(a.View(), a.View(), shift, 20, 15, kUniform), kMaxCost);
}

TEST(Ncc, SubpixelShiftMatchesBilinearWarp) {
  // A linear ramp is reproduced exactly by bilinear sampling, so a shifted
  // ramp matches perfectly.
  Image ramp = test::FlatImage(kW, kH, 0.0f), shifted = ramp;
  for (int r = 0; r < kH; ++r) {
    for (int c = 0; c < kW; ++c) {
      ramp.At(c, r) = 0.01f * c + 0.02f * r + 0.001f * c * c;
      shifted.At(c, r) = 0.01f * (c - 0.5f) + 0.02f * r + 0.001f * (c - 0.5f) * (c - 0.5f);
    }
  }
  const Mat3 H = {{1, 0, 0.5f, 0, 1, 0, 0, 0, 1}};
  EXPECT_NEAR(GeneralNccCost(ramp.View(), shifted.View(), H, 20, 15, kUniform), 0.0f, 2e-3f);
}

}  // namespace
}  // namespace core
}  // namespace msp
