#include "core/cost/ncc.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/math/rng.h"

namespace msp {
namespace core {
namespace {

constexpr int kW = 40, kH = 30;
const Mat3 kIdentity = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};

std::vector<float> Noise(float gain, float offset) {
  std::vector<float> img(kW * kH);
  for (int i = 0; i < kW * kH; ++i) img[i] = offset + gain * RandomUniform(Mix64(99), i);
  return img;
}

ImageView View(const std::vector<float>& img) { return ImageView{img.data(), kW, kH, kW}; }

const NccParams kUniform{5, 2, 0, 5.0f, 0.2f};
const NccParams kBilateral{5, 1, 1, 5.0f, 0.2f};

TEST(Ncc, PatchAgainstItselfCostsZero) {
  const std::vector<float> img = Noise(1.0f, 0.0f);
  EXPECT_NEAR(GeneralNccCost(View(img), View(img), kIdentity, 20, 15, kUniform), 0.0f, 1e-5f);
  EXPECT_NEAR(GeneralNccCost(View(img), View(img), kIdentity, 20, 15, kBilateral), 0.0f, 1e-5f);
  // Near the border only the samples inside the reference count.
  EXPECT_NEAR(GeneralNccCost(View(img), View(img), kIdentity, 1, 2, kUniform), 0.0f, 1e-5f);
}

TEST(Ncc, InvariantToGainAndOffset) {
  const std::vector<float> a = Noise(1.0f, 0.0f);
  const std::vector<float> b = Noise(0.4f, 0.3f);
  EXPECT_NEAR(GeneralNccCost(View(a), View(b), kIdentity, 20, 15, kUniform), 0.0f, 1e-4f);
}

TEST(Ncc, NegatedPatchCostsTwo) {
  const std::vector<float> a = Noise(1.0f, 0.0f);
  const std::vector<float> b = Noise(-1.0f, 1.0f);
  EXPECT_NEAR(GeneralNccCost(View(a), View(b), kIdentity, 20, 15, kUniform), 2.0f, 1e-4f);
}

TEST(Ncc, TexturelessOrOutsideIsMaxCost) {
  const std::vector<float> a = Noise(1.0f, 0.0f);
  const std::vector<float> flat(kW * kH, 0.5f);
  EXPECT_EQ(GeneralNccCost(View(a), View(flat), kIdentity, 20, 15, kUniform), kMaxCost);
  const Mat3 shift = {{1, 0, 100, 0, 1, 0, 0, 0, 1}};  // centre lands outside the source
  EXPECT_EQ(GeneralNccCost(View(a), View(a), shift, 20, 15, kUniform), kMaxCost);
}

TEST(Ncc, SubpixelShiftMatchesBilinearWarp) {
  // A linear ramp is reproduced exactly by bilinear sampling, so a shifted
  // ramp matches perfectly.
  std::vector<float> ramp(kW * kH), shifted(kW * kH);
  for (int r = 0; r < kH; ++r) {
    for (int c = 0; c < kW; ++c) {
      ramp[r * kW + c] = 0.01f * c + 0.02f * r + 0.001f * c * c;
      shifted[r * kW + c] = 0.01f * (c - 0.5f) + 0.02f * r + 0.001f * (c - 0.5f) * (c - 0.5f);
    }
  }
  const Mat3 H = {{1, 0, 0.5f, 0, 1, 0, 0, 0, 1}};
  EXPECT_NEAR(GeneralNccCost(View(ramp), View(shifted), H, 20, 15, kUniform), 0.0f, 2e-3f);
}

}  // namespace
}  // namespace core
}  // namespace msp
