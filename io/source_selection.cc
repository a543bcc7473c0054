// Source-image ranking for `__auto__` and per-image depth ranges, computed as
// COLMAP's mvs::Model does (ComputeSharedPoints, ComputeTriangulationAngles,
// ComputeDepthRanges) from the sparse points' track observations.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/math/camera.h"
#include "io/camera_conversion.h"
#include "io/patch_match_config.h"
#include "io/workspace.h"

namespace msp {
namespace {

// COLMAP ranks by the 75th percentile of the per-point angles between an
// image pair, so a few wide-baseline points cannot carry a narrow pair.
constexpr double kTriangulationAnglePercentile = 75.0;
// ComputeDepthRanges: robust percentiles of the observed depths, then widened
// by 25% on both sides.
constexpr float kMinDepthPercentile = 0.01f;
constexpr float kMaxDepthPercentile = 0.99f;
constexpr float kDepthStretch = 0.25f;

// The percentile rule of COLMAP's depth ranges on `d` (sorted here), in
// float arithmetic as COLMAP so that the chosen indices agree exactly.
std::pair<double, double> RobustRange(std::vector<float>* d) {
  if (d->empty()) return {-1.0, -1.0};
  std::sort(d->begin(), d->end());
  const size_t min_idx = static_cast<size_t>(d->size() * kMinDepthPercentile);
  const size_t max_idx = static_cast<size_t>(d->size() * kMaxDepthPercentile);
  return {(*d)[min_idx] * (1.0f - kDepthStretch), (*d)[max_idx] * (1.0f + kDepthStretch)};
}

Eigen::Matrix3d Rotation(const SparseImage& image) {
  const Eigen::Quaterniond q(image.qvec[0], image.qvec[1], image.qvec[2], image.qvec[3]);
  return q.normalized().toRotationMatrix();
}

Eigen::Vector3d Center(const SparseImage& image) {
  const Eigen::Vector3d t(image.tvec[0], image.tvec[1], image.tvec[2]);
  return -Rotation(image).transpose() * t;
}

// Angle between the rays from the two centres to the point, folded into
// [0, pi/2] (COLMAP's CalculateTriangulationAngle): very acute and very
// obtuse intersections are equally unstable.
double TriangulationAngle(const Eigen::Vector3d& center1, const Eigen::Vector3d& center2,
                          const Eigen::Vector3d& point) {
  const double baseline2 = (center1 - center2).squaredNorm();
  const double ray1 = (point - center1).squaredNorm();
  const double ray2 = (point - center2).squaredNorm();
  const double denominator = 2.0 * std::sqrt(ray1 * ray2);
  if (denominator == 0.0) return 0.0;
  const double cosine = std::clamp((ray1 + ray2 - baseline2) / denominator, -1.0, 1.0);
  const double angle = std::abs(std::acos(cosine));
  return std::min(angle, M_PI - angle);
}

// The angle of an image pair at one point and the number of track-element
// pairs that give it: a track listing image a k times and image b m times
// makes k * m pairs with the same angle. Kept once with its count, a track
// costs the square of its distinct images, not of its length, so no sparse
// model (a corrupt one repeating an image a million times) can make the
// ranking hang or allocate without bound.
struct WeightedAngle {
  double angle;
  int64_t count;
};

// COLMAP's Percentile (the element at round(p/100 * (n-1)) in sorted order) of
// the list with every angle repeated `count` times.
double Percentile(std::vector<WeightedAngle> values, double percentile) {
  int64_t total = 0;
  for (const WeightedAngle& value : values) total += value.count;
  const int64_t idx = std::clamp<int64_t>(
      static_cast<int64_t>(std::round(percentile / 100.0 * static_cast<double>(total - 1))), 0,
      total - 1);
  std::sort(values.begin(), values.end(),
            [](const WeightedAngle& a, const WeightedAngle& b) { return a.angle < b.angle; });
  int64_t seen = 0;
  for (const WeightedAngle& value : values) {
    seen += value.count;
    if (seen > idx) return value.angle;
  }
  return values.back().angle;
}

std::unordered_map<uint32_t, int> ImageIndexById(const SparseModel& model) {
  std::unordered_map<uint32_t, int> index;
  for (size_t i = 0; i < model.images.size(); ++i) {
    index.emplace(model.images[i].image_id, static_cast<int>(i));
  }
  return index;
}

}  // namespace

std::vector<std::vector<int>> SelectAutoSourcesBatch(const SparseModel& model,
                                                     const std::vector<int>& num_per_image,
                                                     double min_triangulation_angle_deg) {
  const size_t num_images = model.images.size();
  std::vector<std::vector<int>> sources(num_images);
  std::vector<bool> wanted(num_images, false);
  for (size_t i = 0; i < num_images && i < num_per_image.size(); ++i) {
    wanted[i] = num_per_image[i] > 0;
  }
  const std::unordered_map<uint32_t, int> index_of = ImageIndexById(model);
  std::vector<Eigen::Vector3d> centers(num_images);
  for (size_t i = 0; i < num_images; ++i) centers[i] = Center(model.images[i]);

  // Each point's distinct images with their counts, and the points of every
  // wanted image: the angles are then made one reference at a time, so that
  // they take memory for one image's pairs, not for every pair of the model
  // (with N images seeing the same points that is N times less).
  std::vector<std::vector<std::pair<int, int64_t>>> distinct_of(model.points3D.size());
  std::vector<std::vector<int>> points_of(num_images);
  std::vector<int> track;
  for (size_t p = 0; p < model.points3D.size(); ++p) {
    track.clear();
    for (const TrackElement& element : model.points3D[p].track) {
      const auto it = index_of.find(element.image_id);
      if (it != index_of.end()) track.push_back(it->second);
    }
    std::sort(track.begin(), track.end());
    std::vector<std::pair<int, int64_t>>& distinct = distinct_of[p];  // (model index, times)
    for (const int index : track) {
      if (distinct.empty() || distinct.back().first != index) distinct.emplace_back(index, 0);
      ++distinct.back().second;
    }
    for (const auto& [index, times] : distinct) {
      if (wanted[index] && distinct.size() > 1) points_of[index].push_back(static_cast<int>(p));
    }
  }
  const double min_angle_rad = min_triangulation_angle_deg * M_PI / 180.0;
  for (size_t ref = 0; ref < num_images; ++ref) {
    if (!wanted[ref]) continue;
    // Per other image: the angle of every co-observation. As in COLMAP every
    // pair of track elements of distinct images counts, so the shared point
    // count is the sum of the counts. The angle is symmetric in the two
    // centres, bit for bit.
    std::map<int, std::vector<WeightedAngle>> angles;
    for (const int p : points_of[ref]) {
      const SparsePoint3D& point = model.points3D[p];
      const Eigen::Vector3d X(point.xyz[0], point.xyz[1], point.xyz[2]);
      const std::vector<std::pair<int, int64_t>>& distinct = distinct_of[p];
      int64_t ref_times = 0;
      for (const auto& [index, times] : distinct) {
        if (index == static_cast<int>(ref)) ref_times = times;
      }
      for (const auto& [other, times] : distinct) {
        if (other == static_cast<int>(ref)) continue;
        angles[other].push_back(
            WeightedAngle{TriangulationAngle(centers[ref], centers[other], X), ref_times * times});
      }
    }
    std::vector<std::pair<int, int64_t>> candidates;  // (model index, shared count)
    for (const auto& [other, other_angles] : angles) {
      if (Percentile(other_angles, kTriangulationAnglePercentile) >= min_angle_rad) {
        int64_t shared = 0;
        for (const WeightedAngle& angle : other_angles) shared += angle.count;
        candidates.emplace_back(other, shared);
      }
    }
    // More shared points first; ties go to the lower model index (the map
    // order) so that the selection does not depend on the sort algorithm.
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    const size_t count = std::min(candidates.size(), static_cast<size_t>(num_per_image[ref]));
    for (size_t i = 0; i < count; ++i) sources[ref].push_back(candidates[i].first);
  }
  return sources;
}

std::vector<int> SelectAutoSources(const SparseModel& model, int ref_index, int num,
                                   double min_triangulation_angle_deg) {
  if (num <= 0 || ref_index < 0 || ref_index >= static_cast<int>(model.images.size())) {
    return {};
  }
  std::vector<int> num_per_image(model.images.size(), 0);
  num_per_image[ref_index] = num;
  return SelectAutoSourcesBatch(model, num_per_image, min_triangulation_angle_deg)[ref_index];
}

std::vector<std::pair<double, double>> ComputeDepthRanges(const SparseModel& model) {
  const size_t num_images = model.images.size();
  const std::unordered_map<uint32_t, int> index_of = ImageIndexById(model);
  std::vector<Eigen::Vector3d> view_dirs(num_images);  // third row of R
  for (size_t i = 0; i < num_images; ++i) view_dirs[i] = Rotation(model.images[i]).row(2);

  std::vector<std::vector<float>> depths(num_images);
  for (const SparsePoint3D& point : model.points3D) {
    const Eigen::Vector3d X(point.xyz[0], point.xyz[1], point.xyz[2]);
    for (const TrackElement& element : point.track) {
      const auto it = index_of.find(element.image_id);
      if (it == index_of.end()) continue;
      const int i = it->second;
      const float depth = static_cast<float>(view_dirs[i].dot(X) + model.images[i].tvec[2]);
      if (depth > 0.0f) depths[i].push_back(depth);
    }
  }

  std::vector<std::pair<double, double>> ranges(num_images, {-1.0, -1.0});
  for (size_t i = 0; i < num_images; ++i) ranges[i] = RobustRange(&depths[i]);
  return ranges;
}

std::vector<std::pair<double, double>> ComputeSharedDepthRanges(
    const SparseModel& model, const std::vector<Problem>& problems) {
  const int num_images = static_cast<int>(model.images.size());
  const std::unordered_map<uint32_t, int> index_of = ImageIndexById(model);
  // The points each image observes, once per point.
  std::vector<std::vector<int>> points_of(num_images);
  for (size_t k = 0; k < model.points3D.size(); ++k) {
    for (const TrackElement& element : model.points3D[k].track) {
      const auto it = index_of.find(element.image_id);
      if (it == index_of.end()) continue;
      std::vector<int>& points = points_of[it->second];
      if (points.empty() || points.back() != static_cast<int>(k)) {
        points.push_back(static_cast<int>(k));
      }
    }
  }
  std::unordered_map<uint32_t, const SparseCamera*> camera_of;
  for (const SparseCamera& c : model.cameras) camera_of[c.camera_id] = &c;
  std::vector<int> stamp(model.points3D.size(), -1);  // the last problem that took the point
  std::vector<std::pair<double, double>> ranges(problems.size(), {-1.0, -1.0});
  for (size_t p = 0; p < problems.size(); ++p) {
    const Problem& problem = problems[p];
    if (problem.ref < 0 || problem.ref >= num_images) continue;
    const SparseImage& image = model.images[problem.ref];
    const auto camera = camera_of.find(image.camera_id);
    if (camera == camera_of.end()) continue;
    const core::Camera cam = MakeCoreCamera(*camera->second, image);
    std::vector<int> views = problem.srcs;
    views.push_back(problem.ref);
    std::vector<float> depths;
    for (int v : views) {
      if (v < 0 || v >= num_images) continue;
      for (int k : points_of[v]) {
        if (stamp[k] == static_cast<int>(p)) continue;
        stamp[k] = static_cast<int>(p);
        const double* xyz = model.points3D[k].xyz;
        const core::Vec3 X{static_cast<float>(xyz[0]), static_cast<float>(xyz[1]),
                           static_cast<float>(xyz[2])};
        const core::Vec3 Xc = core::WorldToCam(cam, X);
        float col, row;
        if (!core::ProjectCamPoint(cam, Xc, &col, &row) || col < 0.0f || row < 0.0f ||
            col > static_cast<float>(cam.width) || row > static_cast<float>(cam.height)) {
          continue;
        }
        depths.push_back(Xc.z);
      }
    }
    ranges[p] = RobustRange(&depths);
  }
  return ranges;
}

std::pair<double, double> ComputeDepthRange(const SparseModel& model, int image_index) {
  if (image_index < 0 || image_index >= static_cast<int>(model.images.size())) {
    return {-1.0, -1.0};
  }
  return ComputeDepthRanges(model)[image_index];
}

}  // namespace msp
