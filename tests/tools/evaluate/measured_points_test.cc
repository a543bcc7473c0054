#include "tools/evaluate/measured_points.h"

#include <gtest/gtest.h>

namespace msp {
namespace eval {
namespace {

// A camera at the origin looking down +z (identity pose), 8x6 pixels, f = 4,
// principal point (4, 3); its ground truth has a measurement everywhere but
// in column 0.
MeasuredView View() {
  MeasuredView view;
  view.camera = core::Camera{};
  view.camera.width = 8;
  view.camera.height = 6;
  view.camera.fx = view.camera.fy = 4.0f;
  view.camera.cx = 4.0f;
  view.camera.cy = 3.0f;
  for (int k = 0; k < 3; ++k) view.camera.R.m[4 * k] = 1.0f;
  view.depth = DenseMap(8, 6, 1, 2.0f);
  for (int r = 0; r < 6; ++r) view.depth.At(r, 0) = 0.0f;
  return view;
}

TEST(MeasuredPoints, JudgedOnlyWhereSomeViewMeasured) {
  const std::vector<Eigen::Vector3f> points = {
      {0.0f, 0.0f, 2.0f},   // centre pixel (4, 3): measured
      {-2.0f, 0.0f, 2.0f},  // column 0: no measurement
      {0.0f, 0.0f, -2.0f},  // behind the camera
      {10.0f, 0.0f, 2.0f},  // outside the image
      {-0.9f, 0.0f, 2.0f},  // column 2.2 -> 2: measured
  };
  const std::vector<uint8_t> judged = MeasuredPoints(points, {View()});
  EXPECT_EQ(judged, (std::vector<uint8_t>{1, 0, 0, 0, 1}));
  // Where 0 means nothing is there (a render's sky), a point seen there is
  // judged: it is a made-up surface, not an unmeasured one.
  EXPECT_EQ(MeasuredPoints(points, {View()}, true), (std::vector<uint8_t>{1, 1, 0, 0, 1}));
}

TEST(MeasuredPoints, AnyViewWithAMeasurementSuffices) {
  MeasuredView shifted = View();
  // The same camera moved 1 m along -x: world x = -2 lands in its column 2.
  shifted.camera.t = core::Vec3{1.0f, 0.0f, 0.0f};
  const std::vector<Eigen::Vector3f> points = {{-2.0f, 0.0f, 2.0f}};
  EXPECT_EQ(MeasuredPoints(points, {View()}), (std::vector<uint8_t>{0}));
  EXPECT_EQ(MeasuredPoints(points, {View(), shifted}), (std::vector<uint8_t>{1}));
  EXPECT_TRUE(MeasuredPoints({}, {View()}).empty());
}

// A point belongs to the view where it lies nearest the ground truth, and is
// textureless when that view's mask says so; a point over no ground truth
// (the sky) is not.
TEST(OnTexturelessSurface, TheNearestViewsMaskDecides) {
  MeasuredView left_blank = View();  // columns 0-3 textureless
  left_blank.textureless = cv::Mat(6, 8, CV_8UC1, cv::Scalar(0));
  left_blank.textureless.colRange(0, 4).setTo(255);
  MeasuredView far = View();  // the same camera, its surface at 4 m, all textureless
  far.depth = DenseMap(8, 6, 1, 4.0f);
  far.textureless = cv::Mat(6, 8, CV_8UC1, cv::Scalar(255));
  const std::vector<Eigen::Vector3f> points = {
      {-0.5f, 0.0f, 2.1f},  // column 3 at 2.1 m: textureless, near the 2 m surface
      {0.5f, 0.0f, 2.0f},   // column 5: textured
      {-2.0f, 0.0f, 2.0f},  // column 0: no ground truth in the first view; the far one has
      {0.5f, 0.0f, 3.9f},   // column 4.5 -> 5 at 3.9 m: nearest the far (textureless) surface
  };
  EXPECT_EQ(OnTexturelessSurface(points, {left_blank, far}), (std::vector<uint8_t>{1, 0, 1, 1}));
  EXPECT_EQ(OnTexturelessSurface(points, {left_blank}), (std::vector<uint8_t>{1, 0, 0, 0}));
  EXPECT_EQ(OnTexturelessSurface(points, {View()}), (std::vector<uint8_t>{0, 0, 0, 0}));
}

}  // namespace
}  // namespace eval
}  // namespace msp
