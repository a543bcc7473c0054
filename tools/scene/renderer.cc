#include "tools/scene/renderer.h"

#include <algorithm>
#include <cmath>

#include "tools/scene/random.h"

namespace msp {
namespace scene {
namespace {

// 2x2 supersampling per pixel (box filter over the pixel's footprint): soft
// object outlines like a real lens, at 4 rays per pixel.
constexpr int kSupersampling = 2;
// A point counts as unoccluded when the first hit towards it is no nearer
// than this fraction of its distance (~35 um at 3.5 m): far above the
// rounding of float-stored surface points, far below any gap between two
// surfaces of the scene (the thinnest object is 12 mm).
constexpr double kVisibilityRelativeTolerance = 1e-5;

uint8_t ToByte(double v) { return static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

}  // namespace

bool GroundTruthAt(const Scene& scene, const PinholeView& view, double col, double row, Hit* hit,
                   double* depth, Eigen::Vector3d* camera_normal) {
  const Eigen::Vector3d center = view.Center();
  if (!scene.Intersect(center, view.RayDirection(col, row), hit)) return false;
  *depth = (view.R * hit->point + view.t).z();
  // The hit normal already faces the ray origin (the camera centre).
  *camera_normal = (view.R * hit->normal).normalized();
  return true;
}

bool IsVisible(const Scene& scene, const PinholeView& view, const Eigen::Vector3d& X, double* col,
               double* row) {
  double c = 0.0, r = 0.0, z = 0.0;
  if (!view.Project(X, &c, &r, &z) || !view.InImage(c, r)) return false;
  const Eigen::Vector3d center = view.Center();
  const Eigen::Vector3d to_point = X - center;
  const double distance = to_point.norm();
  Hit hit;
  if (!scene.Intersect(center, to_point / distance, &hit)) return false;
  if (hit.t < distance * (1.0 - kVisibilityRelativeTolerance)) return false;
  if (col) *col = c;
  if (row) *row = r;
  return true;
}

RenderedView RenderView(const Scene& scene, const PinholeView& view, int view_index,
                        uint64_t seed) {
  const int w = view.width, h = view.height;
  RenderedView out;
  out.image = cv::Mat(h, w, CV_8UC3);
  out.depth = DenseMap(w, h, 1);
  out.normal = DenseMap(w, h, 3);
  out.textureless = cv::Mat(h, w, CV_8UC1, cv::Scalar(0));
  const Eigen::Vector3d center = view.Center();
  const uint64_t noise_stream = kStreamImageNoise + (static_cast<uint64_t>(view_index) << 8);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      Hit hit;
      double depth = 0.0;
      Eigen::Vector3d n;
      if (GroundTruthAt(scene, view, col, row, &hit, &depth, &n)) {
        out.depth.At(row, col) = static_cast<float>(depth);
        for (int c = 0; c < 3; ++c) out.normal.At(row, col, c) = static_cast<float>(n[c]);
        if (scene.materials[hit.material].textureless) out.textureless.at<uint8_t>(row, col) = 255;
      }
      // Anti-aliasing: average sub-pixel rays around the pixel's image point.
      Eigen::Vector3d rgb = Eigen::Vector3d::Zero();
      for (int sy = 0; sy < kSupersampling; ++sy) {
        for (int sx = 0; sx < kSupersampling; ++sx) {
          const double dx = (sx + 0.5) / kSupersampling - 0.5;
          const double dy = (sy + 0.5) / kSupersampling - 0.5;
          Hit sub;
          const Eigen::Vector3d dir = view.RayDirection(col + dx, row + dy);
          rgb += scene.Intersect(center, dir, &sub) ? scene.Radiance(sub) : scene.SkyRadiance(dir);
        }
      }
      rgb /= kSupersampling * kSupersampling;
      const uint64_t pixel = static_cast<uint64_t>(row) * w + col;
      cv::Vec3b& bgr = out.image.at<cv::Vec3b>(row, col);
      for (int c = 0; c < 3; ++c) {
        const double noise = kImageNoiseSigma * StandardNormal(seed, noise_stream, 3 * pixel + c);
        bgr[2 - c] = ToByte(255.0 * rgb[c] + noise);
      }
    }
  }
  return out;
}

}  // namespace scene
}  // namespace msp
