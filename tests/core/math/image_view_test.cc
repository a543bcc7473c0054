#include "core/math/image_view.h"

#include <gtest/gtest.h>

namespace msp {
namespace core {
namespace {

TEST(ImageView, BilinearIsExactOnPlanesAndExplicitOutside) {
  float data[4 * 3];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) data[r * 4 + c] = 2.0f * c + 3.0f * r;
  }
  const ImageView view{data, 4, 3, 4};
  float v = -1.0f;
  ASSERT_TRUE(SampleBilinear(view, 1.25f, 0.5f, &v));
  EXPECT_FLOAT_EQ(v, 2.0f * 1.25f + 3.0f * 0.5f);
  ASSERT_TRUE(SampleBilinear(view, 3.0f, 2.0f, &v));  // last pixel exactly
  EXPECT_FLOAT_EQ(v, 12.0f);
  v = -1.0f;
  EXPECT_FALSE(SampleBilinear(view, -0.01f, 1.0f, &v));
  EXPECT_FALSE(SampleBilinear(view, 1.0f, 2.01f, &v));
  EXPECT_EQ(v, -1.0f);
}

}  // namespace
}  // namespace core
}  // namespace msp
