#include "patch_match/depth_normals.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/parallel_for.h"
#include "core/math/plane.h"

namespace msp {
namespace {

// About 64 radii across the larger side: 8 px at 540 x 360, 10 at 640 x 480.
constexpr int kRadiiAcross = 64;
constexpr int kMinRadius = 3;
// Neighbours on the same surface: depth within this share of the pixel's.
constexpr float kSameSurface = 0.03f;
constexpr int kMinNeighbours = 6;

}  // namespace

int DepthNormalRadius(int width, int height) {
  return std::max(kMinRadius, std::max(width, height) / kRadiiAcross);
}

void NormalsFromDepth(const core::Camera& camera, const DenseMap& depth, int radius,
                      int num_threads, DenseMap* normal) {
  if (depth.channels != 1 || normal->channels != 3 || depth.width != normal->width ||
      depth.height != normal->height) {
    throw std::logic_error("NormalsFromDepth: a 1-channel depth and a 3-channel normal map");
  }
  const int step = std::max(1, radius / 4);
  ParallelFor(0, depth.height, num_threads, [&](int row) {
    for (int col = 0; col < depth.width; ++col) {
      const float d = depth.At(row, col);
      if (!(d > 0.0f)) continue;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      Eigen::Matrix3d sum_sq = Eigen::Matrix3d::Zero();
      int count = 0;
      for (int dy = -radius; dy <= radius; dy += step) {
        const int y = row + dy;
        if (y < 0 || y >= depth.height) continue;
        for (int dx = -radius; dx <= radius; dx += step) {
          const int x = col + dx;
          if (x < 0 || x >= depth.width) continue;
          const float dn = depth.At(y, x);
          if (!(dn > 0.0f) || std::fabs(dn - d) > kSameSurface * d) continue;
          const core::Vec3 X =
              core::BackProject(camera, static_cast<float>(x), static_cast<float>(y), dn);
          const Eigen::Vector3d p(X.x, X.y, X.z);
          sum += p;
          sum_sq += p * p.transpose();
          ++count;
        }
      }
      if (count < kMinNeighbours) continue;
      const Eigen::Vector3d mean = sum / count;
      const Eigen::Matrix3d covariance = sum_sq / count - mean * mean.transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
      const Eigen::Vector3d n = solver.eigenvectors().col(0);  // smallest eigenvalue
      if (!n.allFinite()) continue;
      const core::Vec3 facing =
          core::FaceCamera(camera, col, row,
                           core::Vec3{static_cast<float>(n.x()), static_cast<float>(n.y()),
                                      static_cast<float>(n.z())});
      normal->At(row, col, 0) = facing.x;
      normal->At(row, col, 1) = facing.y;
      normal->At(row, col, 2) = facing.z;
    }
  });
}

}  // namespace msp
