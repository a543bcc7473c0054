#include "tools/scene/tracks.h"

#include <algorithm>
#include <cmath>

#include "tools/scene/random.h"
#include "tools/scene/renderer.h"

namespace msp {
namespace scene {

SparseModel BuildSparseModel(const Scene& scene, const std::vector<PinholeView>& views,
                             const TrackOptions& options, uint64_t seed) {
  SparseModel model;
  const int n = static_cast<int>(views.size());
  for (int i = 0; i < n; ++i) {
    const PinholeView& v = views[i];
    SparseCamera camera;
    camera.camera_id = static_cast<uint32_t>(i + 1);
    camera.model_id = kPinhole;
    camera.width = static_cast<uint64_t>(v.width);
    camera.height = static_cast<uint64_t>(v.height);
    camera.params = {v.fx, v.fy, v.cx, v.cy};
    model.cameras.push_back(camera);
    SparseImage image;
    image.image_id = camera.camera_id;
    image.camera_id = camera.camera_id;
    image.name = v.name;
    RotationToQuaternion(v.R, image.qvec);
    for (int k = 0; k < 3; ++k) image.tvec[k] = v.t[k];
    model.images.push_back(image);
  }
  if (n == 0) return model;

  for (int attempt = 0; attempt < options.max_attempts &&
                        static_cast<int>(model.points3D.size()) < options.num_points;
       ++attempt) {
    const uint64_t key = 4 * static_cast<uint64_t>(attempt);
    const PinholeView& origin = views[attempt % n];
    const double col = Uniform01(seed, kStreamTrackSampling, key) * (origin.width - 1);
    const double row = Uniform01(seed, kStreamTrackSampling, key + 1) * (origin.height - 1);
    Hit hit;
    double depth = 0.0;
    Eigen::Vector3d normal;
    if (!GroundTruthAt(scene, origin, col, row, &hit, &depth, &normal)) continue;
    if (scene.materials[hit.material].textureless &&
        Uniform01(seed, kStreamTrackSampling, key + 2) >= options.textureless_acceptance) {
      continue;
    }
    SparsePoint3D point;
    point.point3D_id = model.points3D.size() + 1;
    for (int k = 0; k < 3; ++k) point.xyz[k] = hit.point[k];
    const Eigen::Vector3d radiance = scene.Radiance(hit);
    for (int k = 0; k < 3; ++k) {
      point.rgb[k] = static_cast<uint8_t>(std::clamp(std::lround(255.0 * radiance[k]), 0L, 255L));
    }
    std::vector<Eigen::Vector2d> observations(n);
    for (int i = 0; i < n; ++i) {
      double c = 0.0, r = 0.0;
      if (!IsVisible(scene, views[i], hit.point, &c, &r)) continue;
      TrackElement element;
      element.image_id = model.images[i].image_id;
      element.point2D_idx = static_cast<uint32_t>(model.images[i].points2D.size());
      point.track.push_back(element);
      observations[i] = {c, r};
    }
    if (point.track.size() < 2) continue;
    for (const TrackElement& element : point.track) {
      const int i = static_cast<int>(element.image_id) - 1;
      Point2D p2d;
      p2d.x = observations[i].x();
      p2d.y = observations[i].y();
      p2d.point3D_id = point.point3D_id;
      model.images[i].points2D.push_back(p2d);
    }
    model.points3D.push_back(std::move(point));
  }
  return model;
}

}  // namespace scene
}  // namespace msp
