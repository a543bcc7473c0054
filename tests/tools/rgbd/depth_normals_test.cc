#include "tools/rgbd/depth_normals.h"

#include <gtest/gtest.h>

#include <cmath>

namespace msp {
namespace rgbd {
namespace {

constexpr int kSize = 20;

scene::PinholeView View() {
  scene::PinholeView view;
  view.width = view.height = kSize;
  view.fx = view.fy = 20.0;
  view.cx = view.cy = 10.0;
  return view;
}

// The depth of the plane n . X = d seen by `view`, quantised to millimetres
// as a depth PNG stores it.
DenseMap PlaneDepth(const scene::PinholeView& view, const Eigen::Vector3d& n, double d) {
  DenseMap depth(kSize, kSize, 1);
  for (int r = 0; r < kSize; ++r) {
    for (int c = 0; c < kSize; ++c) {
      const Eigen::Vector3d ray = view.CameraPoint(c, r, 1.0);
      depth.At(r, c) = static_cast<float>(std::round(1000.0 * d / n.dot(ray)) / 1000.0);
    }
  }
  return depth;
}

Eigen::Vector3d At(const DenseMap& normals, int r, int c) {
  return Eigen::Vector3d(normals.At(r, c, 0), normals.At(r, c, 1), normals.At(r, c, 2));
}

TEST(NormalsFromDepth, SlantedPlaneGivesItsNormalFacingTheCamera) {
  const scene::PinholeView view = View();
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
  const DenseMap normals = NormalsFromDepth(PlaneDepth(view, n, 2.0), view);
  // Facing the camera: the opposite of the plane's normal pointing away.
  EXPECT_LT((At(normals, 10, 10) + n).norm(), 0.01);
  EXPECT_LT((At(normals, 3, 3) + n).norm(), 0.01);  // the first whole window
  EXPECT_EQ(At(normals, 0, 0).norm(), 0.0);         // a corner: 16 of 49 pixels exist
}

TEST(NormalsFromDepth, NoNormalWithoutEnoughMeasuredPixelsOfTheSurface) {
  const scene::PinholeView view = View();
  DenseMap depth = PlaneDepth(view, Eigen::Vector3d::UnitZ(), 2.0);
  // A far background right of column 10 and a hole left of column 3.
  for (int r = 0; r < kSize; ++r) {
    for (int c = 0; c < kSize; ++c) {
      if (c > 10) depth.At(r, c) = 4.0f;
      if (c < 3) depth.At(r, c) = 0.0f;
    }
  }
  const DenseMap normals = NormalsFromDepth(depth, view);
  EXPECT_LT((At(normals, 10, 6) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-6);  // 49 qualify
  EXPECT_EQ(At(normals, 10, 2).norm(), 0.0);                                 // no measurement
  // Column 9 fits its plane to the 5 columns of the wall in its window (35
  // pixels), not to the background; column 12 to 5 columns of the background.
  EXPECT_LT((At(normals, 10, 9) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-6);
  EXPECT_LT((At(normals, 10, 12) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-6);
  // Column 4: only 5 of 7 columns measured and the hole beyond: 35 qualify.
  // Row 0 at column 4: 4 rows x 5 columns = 20 < 25.
  EXPECT_EQ(At(normals, 0, 4).norm(), 0.0);
}

}  // namespace
}  // namespace rgbd
}  // namespace msp
