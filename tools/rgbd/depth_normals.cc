#include "tools/rgbd/depth_normals.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "tools/evaluate/edge_regions.h"
#include "tools/scene/parallel.h"

namespace msp {
namespace rgbd {
namespace {

// The fitted normal of pixel (row, col), or zero.
Eigen::Vector3d PixelNormal(const DenseMap& depth, const scene::PinholeView& view, int row,
                            int col) {
  const double d0 = depth.At(row, col);
  if (!(d0 > 0.0)) return Eigen::Vector3d::Zero();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  int count = 0;
  for (int r = row - kNormalWindowRadius; r <= row + kNormalWindowRadius; ++r) {
    for (int c = col - kNormalWindowRadius; c <= col + kNormalWindowRadius; ++c) {
      if (r < 0 || c < 0 || r >= depth.height || c >= depth.width) continue;
      const double d = depth.At(r, c);
      if (!(d > 0.0) || std::abs(d - d0) > eval::kDepthEdgeJump * std::min(d, d0)) continue;
      const Eigen::Vector3d X = view.CameraPoint(c, r, d);
      sum += X;
      outer += X * X.transpose();
      ++count;
    }
  }
  if (count < kMinNormalSupport) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d mean = sum / count;
  const Eigen::Matrix3d covariance = outer / count - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigenvalues ascend: the first vector is the plane's normal.
  Eigen::Vector3d n = solver.eigenvectors().col(0).normalized();
  if (n.dot(view.CameraPoint(col, row, d0)) > 0.0) n = -n;
  return n;
}

}  // namespace

DenseMap NormalsFromDepth(const DenseMap& depth, const scene::PinholeView& view) {
  DenseMap normals(depth.width, depth.height, 3);
  scene::ParallelIndices(depth.height, [&](int row) {
    for (int col = 0; col < depth.width; ++col) {
      const Eigen::Vector3d n = PixelNormal(depth, view, row, col);
      for (int k = 0; k < 3; ++k) normals.At(row, col, k) = static_cast<float>(n[k]);
    }
  });
  return normals;
}

}  // namespace rgbd
}  // namespace msp
