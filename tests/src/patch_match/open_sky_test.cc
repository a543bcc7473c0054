#include "patch_match/open_sky.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/patch_match/segment_plane.h"
#include "core/patch_match/window_texture.h"
#include "tests/support/cameras.h"

namespace msp {
namespace {

// An accepted plane through (0, 0, 2) with normal `normal`.
SegmentPlane AcceptedPlane(core::Vec3 normal) {
  SegmentPlane plane;
  plane.accepted = true;
  plane.num_inliers = plane.num_own = 100;
  plane.normal = core::Normalized(normal);
  plane.point = core::Vec3{0.0f, 0.0f, 2.0f};
  return plane;
}

// A plane of its own: tilted 30 degrees against the plane the pixels hold.
SegmentPlane OwnPlane() { return AcceptedPlane(core::Vec3{0.577f, 0.0f, -1.0f}); }
// The plane every pixel around holds.
SegmentPlane SurroundingPlane() { return AcceptedPlane(core::Vec3{0.0f, 0.0f, -1.0f}); }

// A 40x30 image cut into vertical strips of 8 columns, segments 1..5 from
// the left; every strip reaches the top and bottom borders unless `closed`.
struct Strips {
  static constexpr int kWidth = 40, kHeight = 30, kStrip = 8;
  std::vector<float> grey = std::vector<float>(kWidth * kHeight, 0.9f);  // bright
  std::vector<int32_t> labels = std::vector<int32_t>(kWidth * kHeight, 0);
  std::vector<float> texture = std::vector<float>(kWidth * kHeight, 0.0f);  // untextured
  std::vector<SegmentPlane> planes = std::vector<SegmentPlane>(6);
  // Every pixel holds the plane z = 2 facing the camera.
  std::vector<float> depth = std::vector<float>(kWidth * kHeight, 2.0f);
  std::vector<float> normal = std::vector<float>(3 * kWidth * kHeight, 0.0f);
  std::vector<float> cost = std::vector<float>(kWidth * kHeight, 0.0f);
  std::vector<uint32_t> mask = std::vector<uint32_t>(kWidth * kHeight, 0u);
  // RGB planes: a pale blue sky colour everywhere.
  DenseMap color = DenseMap(kWidth, kHeight, 3);
  core::PassParams params;

  Strips() {
    for (int i = 0; i < kWidth * kHeight; ++i) normal[2 * kWidth * kHeight + i] = -1.0f;
    SetColor(0, 0.85f, 0.9f, 0.95f);
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) labels[row * kWidth + col] = 1 + col / kStrip;
    }
  }
  // Segment `id`'s pixels set to `value` in `field`.
  template <typename T>
  void Set(int id, std::vector<T>* field, T value) {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == id) (*field)[i] = value;
    }
  }
  // Segment `id`'s pixels (every pixel for 0) in colour (r, g, b).
  void SetColor(int id, float r, float g, float b) {
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        if (id != 0 && labels[row * kWidth + col] != id) continue;
        color.At(row, col, 0) = r;
        color.At(row, col, 1) = g;
        color.At(row, col, 2) = b;
      }
    }
  }
  std::vector<uint8_t> Run() {
    params.state = core::PixelStateView{depth.data(), normal.data(), cost.data(),
                                        mask.data(),  kWidth,        kHeight};
    params.ref_camera = test::CentredCamera(kWidth, kHeight);
    params.ref_image = core::ImageView{grey.data(), kWidth, kHeight, kWidth};
    return OpenSkyPixels(params, color, labels, planes, texture);
  }
  bool Marked(const std::vector<uint8_t>& sky, int id) const {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == id && !sky[i]) return false;
    }
    return true;
  }
};

// Only the segment with no plane of its own that is bright, untextured and
// open to the border is sky; each of the others misses one condition.
TEST(OpenSky, BrightUntexturedOpenSegmentWithoutAPlaneIsSky) {
  Strips s;
  s.planes[2] = OwnPlane();                        // 2: a plane of its own (a white wall)
  s.Set(3, &s.grey, 0.5f);                         // 3: not bright
  s.Set(4, &s.texture, core::kTexturedWindowStd);  // 4: textured
  // 5: closed: moved off the border by giving its border pixels to segment 4.
  for (int row = 0; row < Strips::kHeight; ++row) {
    for (int col = 4 * Strips::kStrip; col < Strips::kWidth; ++col) {
      const bool border = row == 0 || row + 1 == Strips::kHeight || col + 1 == Strips::kWidth;
      if (border) s.labels[row * Strips::kWidth + col] = 4;
    }
  }
  const std::vector<uint8_t> sky = s.Run();
  ASSERT_EQ(sky.size(), s.labels.size());
  EXPECT_TRUE(s.Marked(sky, 1));
  int marked = 0;
  for (size_t i = 0; i < sky.size(); ++i) {
    marked += sky[i];
    if (sky[i]) EXPECT_EQ(s.labels[i], 1);
  }
  EXPECT_EQ(marked, Strips::kStrip * Strips::kHeight);
}

// An accepted plane that the pixels all around the segment hold (the sky in
// a window, given the wall's plane) is no evidence of a surface of its own.
TEST(OpenSky, APlaneThePixelsAroundHoldIsNoEvidence) {
  Strips s;
  for (int id = 2; id <= 5; ++id) s.planes[id] = OwnPlane();
  s.planes[1] = SurroundingPlane();
  EXPECT_TRUE(s.Marked(s.Run(), 1));
  s.planes[1] = OwnPlane();
  EXPECT_TRUE(s.Run().empty());
  // Half of the outline holding it is not yet surrounded: segment 2's
  // pixels in the top half hold segment 1's tilted plane.
  for (int row = 0; row < Strips::kHeight / 2; ++row) {
    const int i = row * Strips::kWidth + Strips::kStrip;
    const core::PlaneHypothesis h = core::HypothesisOnPlane(
        s.params.ref_camera, Strips::kStrip, row, s.planes[1].normal, s.planes[1].point);
    s.depth[i] = h.depth;
    s.normal[i] = h.normal.x;
    s.normal[2 * Strips::kWidth * Strips::kHeight + i] = h.normal.z;
  }
  EXPECT_TRUE(s.Run().empty());
}

// The outline's mixed pixels: the sky takes the neighbours (two deep) whose
// grey is nearer the sky's mean than their own segment's.
TEST(OpenSky, TakesTheMixedPixelsOfItsOutline) {
  Strips s;
  for (int id = 2; id <= 5; ++id) s.Set(id, &s.grey, 0.5f);  // darker surfaces
  for (int id = 2; id <= 5; ++id) s.planes[id] = OwnPlane();
  const int row = 10, first = Strips::kStrip;  // segment 2 starts at column 8
  for (int col = first; col < first + 4; ++col) s.grey[row * Strips::kWidth + col] = 0.8f;
  s.grey[(row + 1) * Strips::kWidth + first] = 0.6f;  // nearer its own segment
  const std::vector<uint8_t> sky = s.Run();
  EXPECT_TRUE(s.Marked(sky, 1));
  EXPECT_EQ(sky[row * Strips::kWidth + first], 1);
  EXPECT_EQ(sky[row * Strips::kWidth + first + 1], 1);
  EXPECT_EQ(sky[row * Strips::kWidth + first + 2], 0);  // three deep
  EXPECT_EQ(sky[(row + 1) * Strips::kWidth + first], 0);
}

// A bright white wall under room light is warm, not blue: not sky, unless it
// is white-out.
TEST(OpenSky, BrightButNotBlueIsNotSkyUnlessWhiteOut) {
  Strips s;
  for (int id = 2; id <= 5; ++id) s.planes[id] = OwnPlane();
  s.SetColor(1, 0.95f, 0.9f, 0.85f);
  EXPECT_TRUE(s.Run().empty());
  s.Set(1, &s.grey, 0.96f);
  EXPECT_TRUE(s.Marked(s.Run(), 1));
}

TEST(OpenSky, NothingMarkedGivesAnEmptyMask) {
  Strips s;
  for (SegmentPlane& plane : s.planes) plane = OwnPlane();
  EXPECT_TRUE(s.Run().empty());
}

TEST(OpenSky, ClearedMapsKeepEverythingElse) {
  DenseMap depth(3, 2, 1, 2.0f), normal(3, 2, 3, 0.5f);
  const std::vector<uint8_t> sky = {0, 1, 0, 0, 0, 1};
  ClearOpenSky(sky, &depth, &normal);
  EXPECT_EQ(depth.At(0, 1), 0.0f);
  EXPECT_EQ(depth.At(1, 2), 0.0f);
  EXPECT_EQ(normal.At(0, 1, 2), 0.0f);
  EXPECT_EQ(depth.At(0, 0), 2.0f);
  EXPECT_EQ(normal.At(1, 1, 0), 0.5f);
  ClearOpenSky({}, &depth, &normal);  // no sky: nothing changes
  EXPECT_EQ(depth.At(0, 0), 2.0f);
  EXPECT_THROW(ClearOpenSky({1, 0}, &depth, &normal), std::logic_error);
}

}  // namespace
}  // namespace msp
