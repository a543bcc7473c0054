#include "tools/evaluate_depth.h"

#include <algorithm>
#include <cmath>

#include "colmap_ext/ground_truth.h"

namespace msp {
namespace eval {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

double Median(std::vector<float>* values) {
  if (values->empty()) return 0.0;
  const size_t mid = values->size() / 2;
  std::nth_element(values->begin(), values->begin() + mid, values->end());
  return (*values)[mid];
}

// Accumulates one region's counts and error lists.
struct RegionAccumulator {
  int num_gt = 0;
  int num_valid = 0;
  int within[2] = {0, 0};
  std::vector<float> rel_errors;
  std::vector<float> normal_errors;

  RegionMetrics Finish() {
    RegionMetrics m;
    m.num_gt = num_gt;
    m.num_valid = num_valid;
    m.valid_fraction = num_gt > 0 ? static_cast<double>(num_valid) / num_gt : 0.0;
    for (int k = 0; k < 2; ++k) {
      m.complete[k] = num_gt > 0 ? static_cast<double>(within[k]) / num_gt : 0.0;
      m.accurate[k] = num_valid > 0 ? static_cast<double>(within[k]) / num_valid : 0.0;
    }
    m.median_rel_error = Median(&rel_errors);
    m.median_normal_error_deg = Median(&normal_errors);
    return m;
  }
};

// Angle between two vectors in degrees; -1 when either is zero.
double AngleDeg(const float a[3], const float b[3]) {
  const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  if (!(na > 0.0) || !(nb > 0.0)) return -1.0;
  const double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (na * nb);
  return std::acos(std::clamp(c, -1.0, 1.0)) * kRadToDeg;
}

void AddRegion(RegionMetrics* sum, const RegionMetrics& m) {
  sum->num_gt += m.num_gt;
  sum->num_valid += m.num_valid;
  sum->valid_fraction += m.valid_fraction;
  for (int k = 0; k < 2; ++k) {
    sum->complete[k] += m.complete[k];
    sum->accurate[k] += m.accurate[k];
  }
  sum->median_rel_error += m.median_rel_error;
  sum->median_normal_error_deg += m.median_normal_error_deg;
}

void DivideRegion(RegionMetrics* m, double n) {
  m->valid_fraction /= n;
  for (int k = 0; k < 2; ++k) {
    m->complete[k] /= n;
    m->accurate[k] /= n;
  }
  m->median_rel_error /= n;
  m->median_normal_error_deg /= n;
}

}  // namespace

DepthMapMetrics EvaluateDepthMap(const DenseMap& depth, const DenseMap& normal,
                                 const DenseMap& gt_depth, const DenseMap& gt_normal,
                                 const cv::Mat& textureless, const double thresholds[2]) {
  DepthMapMetrics out;
  out.width = depth.width;
  out.height = depth.height;
  const bool has_normal =
      normal.channels == 3 && normal.width == depth.width && normal.height == depth.height;
  const bool has_mask = !textureless.empty() && textureless.cols == gt_depth.width &&
                        textureless.rows == gt_depth.height;
  RegionAccumulator all, flat, textured;
  for (int row = 0; row < depth.height; ++row) {
    const int gt_row = NearestGroundTruthIndex(row, depth.height, gt_depth.height);
    for (int col = 0; col < depth.width; ++col) {
      const int gt_col = NearestGroundTruthIndex(col, depth.width, gt_depth.width);
      const float d_gt = gt_depth.At(gt_row, gt_col);
      if (!(d_gt > 0.0f)) continue;
      const bool in_flat = has_mask && textureless.at<uint8_t>(gt_row, gt_col) > 0;
      const float d = depth.At(row, col);
      const bool valid = std::isfinite(d) && d > 0.0f;
      double rel = 0.0, angle = -1.0;
      if (valid) {
        rel = std::abs(static_cast<double>(d) - d_gt) / d_gt;
        if (has_normal) {
          const float n[3] = {normal.At(row, col, 0), normal.At(row, col, 1),
                              normal.At(row, col, 2)};
          const float g[3] = {gt_normal.At(gt_row, gt_col, 0), gt_normal.At(gt_row, gt_col, 1),
                              gt_normal.At(gt_row, gt_col, 2)};
          angle = AngleDeg(n, g);
        }
      }
      for (RegionAccumulator* acc : {&all, in_flat ? &flat : &textured}) {
        ++acc->num_gt;
        if (!valid) continue;
        ++acc->num_valid;
        for (int k = 0; k < 2; ++k) acc->within[k] += rel <= thresholds[k] ? 1 : 0;
        acc->rel_errors.push_back(static_cast<float>(rel));
        if (angle >= 0.0) acc->normal_errors.push_back(static_cast<float>(angle));
      }
    }
  }
  out.all = all.Finish();
  out.textureless = flat.Finish();
  out.textured = textured.Finish();
  return out;
}

DepthMapMetrics AverageMetrics(const std::vector<DepthMapMetrics>& maps) {
  DepthMapMetrics avg;
  avg.name = "average";
  if (maps.empty()) return avg;
  for (const DepthMapMetrics& m : maps) {
    AddRegion(&avg.all, m.all);
    AddRegion(&avg.textureless, m.textureless);
    AddRegion(&avg.textured, m.textured);
  }
  DivideRegion(&avg.all, static_cast<double>(maps.size()));
  DivideRegion(&avg.textureless, static_cast<double>(maps.size()));
  DivideRegion(&avg.textured, static_cast<double>(maps.size()));
  return avg;
}

}  // namespace eval
}  // namespace msp
