#include "tools/evaluate/evaluate_depth.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "io/ground_truth.h"

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
  int within_abs[2] = {0, 0};
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
      m.complete_abs[k] = num_gt > 0 ? static_cast<double>(within_abs[k]) / num_gt : 0.0;
      m.accurate_abs[k] = num_valid > 0 ? static_cast<double>(within_abs[k]) / num_valid : 0.0;
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

// A region's mean over the images that have a figure for it.
struct RegionSum {
  RegionMetrics sum;
  int count = 0;
};

void AddRegion(RegionSum* total, const RegionMetrics& m, bool missing) {
  total->sum.num_gt += m.num_gt;
  total->sum.num_valid += m.num_valid;
  if (!missing && m.num_gt == 0) return;
  ++total->count;
  RegionMetrics* sum = &total->sum;
  sum->valid_fraction += m.valid_fraction;
  for (int k = 0; k < 2; ++k) {
    sum->complete[k] += m.complete[k];
    sum->accurate[k] += m.accurate[k];
    sum->complete_abs[k] += m.complete_abs[k];
    sum->accurate_abs[k] += m.accurate_abs[k];
  }
  sum->median_rel_error += m.median_rel_error;
  sum->median_normal_error_deg += m.median_normal_error_deg;
}

RegionMetrics Mean(const RegionSum& total) {
  RegionMetrics m = total.sum;
  if (total.count == 0) return m;
  const double n = total.count;
  m.valid_fraction /= n;
  for (int k = 0; k < 2; ++k) {
    m.complete[k] /= n;
    m.accurate[k] /= n;
    m.complete_abs[k] /= n;
    m.accurate_abs[k] /= n;
  }
  m.median_rel_error /= n;
  m.median_normal_error_deg /= n;
  return m;
}

double WithDepthFraction(const EmptyMetrics& m) {
  return m.num_empty > 0 ? static_cast<double>(m.num_with_depth) / m.num_empty : 0.0;
}

bool InMask(const cv::Mat& mask, int row, int col) {
  return !mask.empty() && mask.at<uint8_t>(row, col) > 0;
}

// An empty mask, or one of the ground truth's size.
void CheckMask(const cv::Mat& mask, const DenseMap& gt, const char* what) {
  if (mask.empty()) return;
  if (mask.type() != CV_8UC1 || mask.cols != gt.width || mask.rows != gt.height) {
    throw std::invalid_argument(std::string("EvaluateDepthMap: the ") + what +
                                " mask is not CV_8UC1 at the ground truth's size");
  }
}

}  // namespace

DepthMapMetrics EvaluateDepthMap(const DenseMap& depth, const DenseMap& normal,
                                 const DenseMap& gt_depth, const DenseMap& gt_normal,
                                 const RegionMasks& masks, const DepthThresholds& thresholds,
                                 bool zero_is_empty) {
  DepthMapMetrics out;
  out.width = depth.width;
  out.height = depth.height;
  const bool has_normal = normal.channels == 3 && normal.width == depth.width &&
                          normal.height == depth.height && gt_normal.channels == 3 &&
                          gt_normal.width == gt_depth.width && gt_normal.height == gt_depth.height;
  CheckMask(masks.textureless, gt_depth, "textureless");
  CheckMask(masks.near_edge, gt_depth, "near-edge");
  CheckMask(masks.alike_edge, gt_depth, "alike-edge");
  RegionAccumulator all, flat, textured, near_edge, alike_edge;
  for (int row = 0; row < depth.height; ++row) {
    const int gt_row = NearestGroundTruthIndex(row, depth.height, gt_depth.height);
    for (int col = 0; col < depth.width; ++col) {
      const int gt_col = NearestGroundTruthIndex(col, depth.width, gt_depth.width);
      const float d_gt = gt_depth.At(gt_row, gt_col);
      if (!(d_gt > 0.0f)) {
        if (zero_is_empty) {
          const float d = depth.At(row, col);
          ++out.empty.num_empty;
          out.empty.num_with_depth += std::isfinite(d) && d > 0.0f ? 1 : 0;
        }
        continue;
      }
      RegionAccumulator* regions[4] = {&all, nullptr, nullptr, nullptr};
      regions[1] = InMask(masks.textureless, gt_row, gt_col) ? &flat : &textured;
      if (InMask(masks.near_edge, gt_row, gt_col)) regions[2] = &near_edge;
      if (InMask(masks.alike_edge, gt_row, gt_col)) regions[3] = &alike_edge;
      const float d = depth.At(row, col);
      const bool valid = std::isfinite(d) && d > 0.0f;
      double rel = 0.0, abs_error = 0.0, angle = -1.0;
      if (valid) {
        abs_error = std::abs(static_cast<double>(d) - d_gt);
        rel = abs_error / d_gt;
        if (has_normal) {
          const float n[3] = {normal.At(row, col, 0), normal.At(row, col, 1),
                              normal.At(row, col, 2)};
          const float g[3] = {gt_normal.At(gt_row, gt_col, 0), gt_normal.At(gt_row, gt_col, 1),
                              gt_normal.At(gt_row, gt_col, 2)};
          angle = AngleDeg(n, g);
        }
      }
      for (RegionAccumulator* acc : regions) {
        if (acc == nullptr) continue;
        ++acc->num_gt;
        if (!valid) continue;
        ++acc->num_valid;
        for (int k = 0; k < 2; ++k) {
          acc->within[k] += rel <= thresholds.relative[k] ? 1 : 0;
          acc->within_abs[k] += abs_error <= thresholds.absolute[k] ? 1 : 0;
        }
        acc->rel_errors.push_back(static_cast<float>(rel));
        if (angle >= 0.0) acc->normal_errors.push_back(static_cast<float>(angle));
      }
    }
  }
  out.all = all.Finish();
  out.textureless = flat.Finish();
  out.textured = textured.Finish();
  out.near_edge = near_edge.Finish();
  out.alike_edge = alike_edge.Finish();
  out.empty.with_depth_fraction = WithDepthFraction(out.empty);
  return out;
}

DepthMapMetrics AverageMetrics(const std::vector<DepthMapMetrics>& maps) {
  DepthMapMetrics avg;
  avg.name = "average";
  RegionSum all, flat, textured, near_edge, alike_edge;
  for (const DepthMapMetrics& m : maps) {
    AddRegion(&all, m.all, m.missing);
    AddRegion(&flat, m.textureless, m.missing);
    AddRegion(&textured, m.textured, m.missing);
    AddRegion(&near_edge, m.near_edge, m.missing);
    AddRegion(&alike_edge, m.alike_edge, m.missing);
    if (!m.missing && avg.edge_band_radius == 0) avg.edge_band_radius = m.edge_band_radius;
    avg.empty.num_empty += m.empty.num_empty;
    avg.empty.num_with_depth += m.empty.num_with_depth;
  }
  avg.all = Mean(all);
  avg.textureless = Mean(flat);
  avg.textured = Mean(textured);
  avg.near_edge = Mean(near_edge);
  avg.alike_edge = Mean(alike_edge);
  avg.empty.with_depth_fraction = WithDepthFraction(avg.empty);
  return avg;
}

}  // namespace eval
}  // namespace msp
