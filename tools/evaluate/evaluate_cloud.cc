#include "tools/evaluate/evaluate_cloud.h"

#include "tools/evaluate/point_grid.h"

namespace msp {
namespace eval {

double F1Score(double precision, double recall) {
  return precision + recall > 0.0 ? 2.0 * precision * recall / (precision + recall) : 0.0;
}

std::vector<CloudThreshold> CloudThresholds(double extent, const std::vector<double>& fractions,
                                            const std::vector<double>& metres) {
  std::vector<CloudThreshold> thresholds;
  for (const double fraction : fractions) thresholds.push_back({fraction * extent, false});
  for (const double m : metres) thresholds.push_back({m, true});
  return thresholds;
}

CloudMetrics EvaluateCloud(const std::vector<Eigen::Vector3f>& points,
                           const std::vector<uint8_t>& judged,
                           const std::vector<Eigen::Vector3f>& gt_points,
                           const std::vector<uint8_t>& gt_views, int min_views, double extent,
                           const std::vector<CloudThreshold>& thresholds) {
  CloudMetrics out;
  out.num_points = static_cast<int>(points.size());
  out.num_gt = static_cast<int>(gt_points.size());
  out.min_views = min_views;
  const bool has_views = gt_views.size() == gt_points.size();
  const bool has_judged = judged.size() == points.size();
  for (size_t i = 0; i < gt_points.size(); ++i) {
    out.num_gt_multi += (!has_views || gt_views[i] >= min_views) ? 1 : 0;
  }
  for (size_t i = 0; i < points.size(); ++i) out.num_judged += (!has_judged || judged[i]) ? 1 : 0;
  for (const CloudThreshold& threshold : thresholds) {
    CloudThresholdMetrics m;
    m.metres = threshold.metres;
    m.absolute = threshold.absolute;
    m.fraction = extent > 0.0 ? threshold.metres / extent : 0.0;
    if (m.metres > 0.0) {
      const PointGrid gt_grid(gt_points, m.metres);
      const PointGrid grid(points, m.metres);
      int accurate = 0;
      for (size_t i = 0; i < points.size(); ++i) {
        if (has_judged && !judged[i]) continue;
        accurate += gt_grid.HasNeighbor(points[i]) ? 1 : 0;
      }
      int covered = 0, covered_multi = 0;
      for (size_t i = 0; i < gt_points.size(); ++i) {
        if (!grid.HasNeighbor(gt_points[i])) continue;
        ++covered;
        if (!has_views || gt_views[i] >= min_views) ++covered_multi;
      }
      m.accuracy = out.num_judged > 0 ? static_cast<double>(accurate) / out.num_judged : 0.0;
      m.completeness = gt_points.empty() ? 0.0 : static_cast<double>(covered) / gt_points.size();
      m.completeness_multi =
          out.num_gt_multi > 0 ? static_cast<double>(covered_multi) / out.num_gt_multi : 0.0;
    }
    m.f1 = F1Score(m.accuracy, m.completeness);
    m.f1_multi = F1Score(m.accuracy, m.completeness_multi);
    out.thresholds.push_back(m);
  }
  return out;
}

}  // namespace eval
}  // namespace msp
