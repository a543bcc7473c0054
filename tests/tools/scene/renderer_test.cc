#include "tools/scene/renderer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "tools/scene/shapes.h"

namespace msp {
namespace scene {
namespace {

// A camera at height h above the floor of an empty room, looking straight
// down: every pixel's ray hits the plane z = 0.
PinholeView DownLookingView(double h) {
  PinholeView v;
  v.width = 64;
  v.height = 48;
  v.fx = v.fy = 50.0;
  v.cx = 32.0;
  v.cy = 24.0;
  // Camera z (forward) = world -z; camera x = world x; camera y = world -y.
  v.R << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  const Eigen::Vector3d center(2.0, 2.0, h);
  v.t = -v.R * center;
  return v;
}

Scene EmptyRoom() {
  Scene scene = MakeRoomScene();
  scene.shapes.resize(1);  // the room only
  return scene;
}

TEST(Shapes, RayHitsKnownPlaneAtExactDistance) {
  Shape room;
  room.type = ShapeType::kRoom;
  room.hi = Eigen::Vector3d(5, 5, 2.5);
  double t = 0;
  Eigen::Vector3d n;
  int face = -1;
  ASSERT_TRUE(IntersectRoom(room, {1, 1, 1}, Eigen::Vector3d(-1, 0, 0), 1e-9, &t, &n, &face));
  EXPECT_DOUBLE_EQ(t, 1.0);
  EXPECT_EQ(n, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(face, 0);
}

TEST(Shapes, SphereBoxAndCylinderNormalsFaceTheRay) {
  Shape sphere;
  sphere.type = ShapeType::kSphere;
  sphere.center = {0, 0, 0};
  sphere.radius = 1.0;
  double t = 0;
  Eigen::Vector3d n;
  ASSERT_TRUE(IntersectSphere(sphere, {0, 0, 5}, {0, 0, -1}, 1e-9, &t, &n));
  EXPECT_DOUBLE_EQ(t, 4.0);
  EXPECT_EQ(n, Eigen::Vector3d(0, 0, 1));

  Shape box;
  box.lo = {-1, -1, -1};
  box.hi = {1, 1, 1};
  ASSERT_TRUE(IntersectBox(box, {3, 0.5, 0.2}, {-1, 0, 0}, 1e-9, &t, &n));
  EXPECT_DOUBLE_EQ(t, 2.0);
  EXPECT_EQ(n, Eigen::Vector3d(1, 0, 0));
  EXPECT_FALSE(IntersectBox(box, {3, 1.5, 0.2}, {-1, 0, 0}, 1e-9, &t, &n));

  Shape cyl;
  cyl.type = ShapeType::kCylinder;
  cyl.center = {0, 0, 0};
  cyl.radius = 0.5;
  cyl.lo = {0, 0, 0};
  cyl.hi = {0, 0, 2};
  ASSERT_TRUE(IntersectCylinder(cyl, {0, -3, 1}, {0, 1, 0}, 1e-9, &t, &n));
  EXPECT_DOUBLE_EQ(t, 2.5);
  EXPECT_EQ(n, Eigen::Vector3d(0, -1, 0));
  ASSERT_TRUE(IntersectCylinder(cyl, {0.1, 0, 4}, {0, 0, -1}, 1e-9, &t, &n));  // top cap
  EXPECT_DOUBLE_EQ(t, 2.0);
  EXPECT_EQ(n, Eigen::Vector3d(0, 0, 1));
}

TEST(Renderer, GroundTruthOfAPlaneIsExact) {
  const Scene scene = EmptyRoom();
  const double h = 1.5;
  const PinholeView view = DownLookingView(h);
  for (const auto& px : {std::pair<int, int>{32, 24}, {0, 0}, {63, 47}, {10, 40}}) {
    Hit hit;
    double depth = 0;
    Eigen::Vector3d n;
    ASSERT_TRUE(GroundTruthAt(scene, view, px.first, px.second, &hit, &depth, &n));
    // Fronto-parallel floor: camera z is the height everywhere (not the ray length).
    EXPECT_NEAR(depth, h, 1e-12);
    EXPECT_NEAR((n - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-12);
    // The point back-projects through the pixel (COLMAP MVS: no +0.5).
    EXPECT_NEAR(hit.point.x(), 2.0 + h * (px.first - view.cx) / view.fx, 1e-12);
    EXPECT_NEAR(hit.point.y(), 2.0 - h * (px.second - view.cy) / view.fy, 1e-12);
  }
  const RenderedView r = RenderView(scene, view, 0, 1);
  EXPECT_FLOAT_EQ(r.depth.At(5, 7), static_cast<float>(h));
  EXPECT_FLOAT_EQ(r.normal.At(5, 7, 2), -1.0f);
  EXPECT_EQ(r.textureless.at<uint8_t>(5, 7), 255);
}

TEST(Renderer, TiltedPlaneNormalFacesTheCamera) {
  const Scene scene = EmptyRoom();
  // Looking at the x = 0 wall at 45 degrees in the horizontal plane.
  PinholeView view;
  view.width = 32;
  view.height = 32;
  view.fx = view.fy = 40;
  view.cx = view.cy = 16;
  const Eigen::Vector3d center(1, 1, 1);
  const Eigen::Vector3d forward = Eigen::Vector3d(-1, -1, 0).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  view.R.row(0) = right;
  view.R.row(1) = forward.cross(right);
  view.R.row(2) = forward;
  view.t = -view.R * center;
  const RenderedView r = RenderView(scene, view, 0, 1);
  // The centre ray hits the corner; left of it is the x = 0 wall or y = 0 wall.
  for (const auto& px : {std::pair<int, int>{4, 16}, {28, 16}}) {
    const Eigen::Vector3d n(r.normal.At(px.second, px.first, 0),
                            r.normal.At(px.second, px.first, 1),
                            r.normal.At(px.second, px.first, 2));
    const Eigen::Vector3d ray((px.first - view.cx) / view.fx, (px.second - view.cy) / view.fy, 1);
    EXPECT_NEAR(n.norm(), 1.0, 1e-6);
    EXPECT_LT(n.dot(ray), 0.0);
    // A wall is vertical: its camera-frame normal makes 45 degrees with the axis.
    EXPECT_NEAR(std::abs(n.z()), std::sqrt(0.5), 1e-6);
  }
}

TEST(Renderer, VisibilityRespectsOcclusionAndImageBounds) {
  Scene scene = EmptyRoom();
  Shape box;
  box.lo = {1.9, 1.9, 0.0};
  box.hi = {2.1, 2.1, 0.5};
  scene.shapes.push_back(box);
  const PinholeView view = DownLookingView(1.5);
  double col = 0, row = 0;
  EXPECT_FALSE(IsVisible(scene, view, {2.0, 2.0, 0.0}));             // under the box
  EXPECT_TRUE(IsVisible(scene, view, {2.0, 2.0, 0.5}, &col, &row));  // its top
  EXPECT_NEAR(col, 32.0, 1e-9);
  EXPECT_NEAR(row, 24.0, 1e-9);
  EXPECT_TRUE(IsVisible(scene, view, {2.5, 2.0, 0.0}));
  EXPECT_FALSE(IsVisible(scene, view, {4.5, 2.0, 0.0}));  // outside the image
}

TEST(Renderer, WallsAreNearlyTexturelessAndObjectsTextured) {
  // The scene's reason to exist: local contrast on walls / floor is at the
  // noise level, on textured objects far above it.
  const Scene scene = MakeRoomScene();
  const PinholeView view = MakeCameraRig(RigOptions(), 1)[0];
  const RenderedView r = RenderView(scene, view, 0, 1);
  cv::Mat gray;
  cv::Mat(r.image).convertTo(gray, CV_32FC3);
  cv::Mat channels[3];
  cv::split(gray, channels);
  const cv::Mat g = (channels[0] + channels[1] + channels[2]) / 3.0;
  constexpr int kRadius = 5;  // 11x11 windows, as the matching cost uses
  std::vector<double> flat;
  double textured_sum = 0;
  int textured_n = 0;
  for (int y = kRadius; y + kRadius < g.rows; y += 4) {
    for (int x = kRadius; x + kRadius < g.cols; x += 4) {
      const cv::Mat window =
          g(cv::Rect(x - kRadius, y - kRadius, 2 * kRadius + 1, 2 * kRadius + 1));
      const cv::Mat mask =
          r.textureless(cv::Rect(x - kRadius, y - kRadius, 2 * kRadius + 1, 2 * kRadius + 1));
      const int n = cv::countNonZero(mask);
      cv::Scalar mean, stddev;
      cv::meanStdDev(window, mean, stddev);
      if (n == static_cast<int>(mask.total())) {
        flat.push_back(stddev[0]);
      } else if (n == 0) {
        textured_sum += stddev[0];
        ++textured_n;
      }
    }
  }
  ASSERT_GT(flat.size(), 1000u);
  ASSERT_GT(textured_n, 50);
  // The median window is the wall itself (0.69 grey levels; the noise alone,
  // sigma 1 per channel, is 0.58 in the grey mean). The mean moved with how
  // many windows straddle the deliberate alike-colour depth edges (2.04 with
  // the sky window, which hides some plain wall), so it is not the figure.
  std::nth_element(flat.begin(), flat.begin() + flat.size() / 2, flat.end());
  const double flat_median = flat[flat.size() / 2];
  const double textured = textured_sum / textured_n;
  EXPECT_LT(flat_median, 1.0) << "walls/floor should only carry camera noise";
  EXPECT_GT(textured, 15.0);
  // Most of the image is textureless surface.
  EXPECT_GT(cv::countNonZero(r.textureless), r.textureless.total() / 2);
}

}  // namespace
}  // namespace scene
}  // namespace msp
