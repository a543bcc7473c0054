// ETH3D-style point-cloud figures: accuracy (fraction of reconstructed points
// within a distance of the ground-truth surface sample), completeness
// (fraction of ground-truth samples within that distance of a reconstructed
// point) and their harmonic mean F1.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace msp {
namespace eval {

// One distance the figures are taken at.
struct CloudThreshold {
  double metres = 0.0;
  bool absolute = false;  // given in metres, not as a fraction of the scene extent
};

// The relative thresholds (fractions of `extent`) first, in their order, then
// the absolute ones (metres): the order of CloudMetrics::thresholds.
std::vector<CloudThreshold> CloudThresholds(double extent, const std::vector<double>& fractions,
                                            const std::vector<double>& metres);

struct CloudThresholdMetrics {
  double fraction = 0.0;  // threshold as a fraction of the scene extent
  double metres = 0.0;
  bool absolute = false;            // see CloudThreshold
  double accuracy = 0.0;            // over the judged points
  double completeness = 0.0;        // over all ground-truth samples
  double completeness_multi = 0.0;  // over samples seen by >= min_views views
  double f1 = 0.0;                  // from accuracy and completeness
  double f1_multi = 0.0;            // from accuracy and completeness_multi
};

struct CloudMetrics {
  int num_points = 0;    // reconstructed
  int num_judged = 0;    // of those, the ones accuracy counts (see EvaluateCloud)
  int num_gt = 0;        // ground-truth samples
  int num_gt_multi = 0;  // ground-truth samples seen by >= min_views views
  int min_views = 0;
  std::vector<CloudThresholdMetrics> thresholds;
};

double F1Score(double precision, double recall);

// `judged` marks the reconstructed points accuracy counts (same size as
// points; empty: all of them): where the ground truth has no measurement a
// point is no evidence either way (MeasuredPoints, measured_points.h).
// `gt_views` holds the number of views per ground-truth sample (same size as
// gt_points); when empty every sample counts as multi-view.
CloudMetrics EvaluateCloud(const std::vector<Eigen::Vector3f>& points,
                           const std::vector<uint8_t>& judged,
                           const std::vector<Eigen::Vector3f>& gt_points,
                           const std::vector<uint8_t>& gt_views, int min_views, double extent,
                           const std::vector<CloudThreshold>& thresholds);

}  // namespace eval
}  // namespace msp
