#include "options/option_check.h"

#include <initializer_list>
#include <sstream>
#include <string>

#include "core/deformable/anchors.h"
#include "core/deformable/synergistic_optimization.h"
#include "core/prior/prior_limits.h"
#include "options/option_name.h"
#include "options/shard_spec.h"

namespace msp {
namespace {

// Below this the coarsest round has too few pixels for an 11x11 window.
constexpr int kMinCoarsestImageSize = 64;

template <typename T>
std::string ToText(const T& value) {
  std::ostringstream stream;
  stream << value;
  return stream.str();
}

[[noreturn]] void Fail(const std::string& option, const std::string& value,
                       const std::string& allowed) {
  throw OptionError("invalid value " + value + " for --" + option + ": must be " + allowed);
}

// Which ends of an interval belong to it: [lo, hi], [lo, hi) or (lo, hi).
enum class Interval { kClosed, kOpenHigh, kOpen };

// `why` (with its leading space) follows the interval in the message.
template <typename T>
void CheckRange(const std::string& option, T value, T lo, T hi,
                Interval interval = Interval::kClosed, const std::string& why = "") {
  const bool lo_open = interval == Interval::kOpen;
  const bool hi_open = interval != Interval::kClosed;
  const bool ok = (lo_open ? value > lo : value >= lo) && (hi_open ? value < hi : value <= hi);
  if (!ok) {
    Fail(option, ToText(value),
         "in " + std::string(lo_open ? "(" : "[") + ToText(lo) + ", " + ToText(hi) +
             (hi_open ? ")" : "]") + why);
  }
}

template <typename T>
void CheckPositive(const std::string& option, T value) {
  if (!(value > T(0))) Fail(option, ToText(value), "> 0");
}

template <typename T>
void CheckNonNegative(const std::string& option, T value) {
  if (!(value >= T(0))) Fail(option, ToText(value), ">= 0");
}

void CheckOneOf(const std::string& option, const std::string& value,
                std::initializer_list<const char*> allowed) {
  std::string list;
  for (const char* entry : allowed) {
    if (value == entry) return;
    list += (list.empty() ? "" : ", ") + std::string(entry);
  }
  Fail(option, "`" + value + "`", "one of {" + list + "}");
}

// Each rule takes the options struct and the bare field; the message names
// the option as MSP_OPTION_NAME spells it from the field.
#define MSP_CHECK_RANGE(options, field, ...) \
  CheckRange(MSP_OPTION_NAME(options, field), (options).field, __VA_ARGS__)
#define MSP_CHECK_POSITIVE(options, field) \
  CheckPositive(MSP_OPTION_NAME(options, field), (options).field)
#define MSP_CHECK_NON_NEGATIVE(options, field) \
  CheckNonNegative(MSP_OPTION_NAME(options, field), (options).field)
#define MSP_CHECK_ONE_OF(options, field, ...) \
  CheckOneOf(MSP_OPTION_NAME(options, field), (options).field, {__VA_ARGS__})

void CheckDepthRange(const PatchMatchStereoOptions& o) {
  // COLMAP: both -1 = per-image range from the sparse model; otherwise a
  // manual range with 0 <= min <= max.
  if (o.depth_min == -1.0 && o.depth_max == -1.0) return;
  const std::string min_flag = MSP_OPTION_FLAG(o, depth_min);
  const std::string max_flag = MSP_OPTION_FLAG(o, depth_max);
  if (!(o.depth_min >= 0.0)) {
    Fail(MSP_OPTION_NAME(o, depth_min), ToText(o.depth_min),
         "-1 (automatic, with " + max_flag + " -1) or in [0, " + max_flag + " = " +
             ToText(o.depth_max) + "]");
  }
  if (!(o.depth_max >= o.depth_min)) {
    Fail(
        MSP_OPTION_NAME(o, depth_max), ToText(o.depth_max),
        "-1 (automatic, with " + min_flag + " -1) or >= " + min_flag + " = " + ToText(o.depth_min));
  }
}

}  // namespace

void CheckPatchMatchStereoOptions(const PatchMatchStereoOptions& o) {
  CheckDepthRange(o);
  MSP_CHECK_RANGE(o, window_radius, 1, kMaxWindowRadius, Interval::kClosed,
                  " (the widest window the back-ends hold, kMaxWindowRadius; COLMAP allows 32)");
  MSP_CHECK_RANGE(o, window_step, 1, 2);
  MSP_CHECK_POSITIVE(o, sigma_color);
  MSP_CHECK_POSITIVE(o, num_samples);
  MSP_CHECK_POSITIVE(o, ncc_sigma);
  MSP_CHECK_RANGE(o, min_triangulation_angle, 0.0, 180.0, Interval::kOpenHigh);
  MSP_CHECK_POSITIVE(o, incident_angle_sigma);
  MSP_CHECK_POSITIVE(o, num_iterations);
  MSP_CHECK_NON_NEGATIVE(o, geom_consistency_regularizer);
  MSP_CHECK_NON_NEGATIVE(o, geom_consistency_max_cost);
  MSP_CHECK_RANGE(o, filter_min_ncc, -1.0, 1.0);
  MSP_CHECK_RANGE(o, filter_min_triangulation_angle, 0.0, 180.0);
  MSP_CHECK_NON_NEGATIVE(o, filter_min_num_consistent);
  MSP_CHECK_NON_NEGATIVE(o, filter_geom_consistency_max_cost);
  MSP_CHECK_POSITIVE(o, cache_size);
}

void CheckMspStereoOptions(const MspStereoOptions& o) {
  MSP_CHECK_ONE_OF(o, backend, "auto", "cpu", "cuda");
  if (!o.shard.empty()) ParseShardSpec(o.shard);
  if (!o.shard.empty() && !o.image_list.empty()) {
    Fail(MSP_OPTION_NAME(o, image_list), "`" + o.image_list + "`",
         "\"\" with " + MSP_OPTION_FLAG(o, shard) + " (a process takes a shard or a list)");
  }
  MSP_CHECK_POSITIVE(o, shard_timeout);
  MSP_CHECK_RANGE(o, advanced_coarsest_image_size, kMinCoarsestImageSize, 1 << 20,
                  Interval::kClosed, " (smaller images have too few pixels to match)");
  MSP_CHECK_RANGE(o, advanced_iterations, 1, 3);
  MSP_CHECK_NON_NEGATIVE(o, advanced_deformable_max_image_size);
  MSP_CHECK_NON_NEGATIVE(o, advanced_restoring_image_size);
  MSP_CHECK_RANGE(o, advanced_finest_iterations, 1, 3);
  MSP_CHECK_RANGE(o, black_level, 0.0, 1.0);
  MSP_CHECK_RANGE(o, filter_max_depth_error, 0.0, 1.0);
  MSP_CHECK_RANGE(o, filter_single_view_depth_error, 0.0, 1.0);
  MSP_CHECK_RANGE(o, geom_consistency_depth_error, 0.0, 1.0);
  MSP_CHECK_NON_NEGATIVE(o, geom_consistency_depth_weight);
  MSP_CHECK_RANGE(o, advanced_finest_refine_radius, 1, 5);  // 5 = core::kLocalRefineRadius
  MSP_CHECK_RANGE(o, advanced_geometric_passes, 1,
                  3);  // 3 = kNumGeometricPasses, the most a round has
  MSP_CHECK_RANGE(o, advanced_finest_geometric_passes, 1, 3);
  MSP_CHECK_RANGE(o, window_step, 1, 2);
  MSP_CHECK_RANGE(o, advanced_reliable_max_cost, 0.0, 2.0);
  MSP_CHECK_RANGE(o, advanced_reliable_single_cost, 0.0, 2.0);
  MSP_CHECK_RANGE(o, advanced_reliable_min_spread, 0.0, 2.0);
  MSP_CHECK_RANGE(o, advanced_anchor_max_distance, core::kFirstRayRadius, 1 << 16,
                  Interval::kClosed, " (the first ray sample lies 2 px from the pixel)");
  MSP_CHECK_RANGE(o, advanced_equidistribution_iterations, 1, core::kMaxEquidistributionIterations);
  MSP_CHECK_RANGE(o, advanced_num_mask_levels, 1, core::kMaxLabelLayers, Interval::kClosed,
                  " (best-layer sets are 32-bit sets, kMaxLabelLayers)");
  if (o.geometry_layers) {
    MSP_CHECK_RANGE(o, advanced_num_mask_levels, 1,
                    core::kMaxLabelLayers - core::kNumGeometryLayers, Interval::kClosed,
                    " with " + MSP_OPTION_FLAG(o, geometry_layers) + ", which adds " +
                        std::to_string(core::kNumGeometryLayers) + " (kMaxLabelLayers = " +
                        std::to_string(core::kMaxLabelLayers) + " in all)");
  }
  MSP_CHECK_ONE_OF(o, segmenter, "opencv", "embedded");
  MSP_CHECK_POSITIVE(o, advanced_crf_alpha);
  MSP_CHECK_POSITIVE(o, advanced_crf_beta);
  MSP_CHECK_RANGE(o, advanced_crf_unary_confidence, 0.0, 1.0, Interval::kOpen);
  MSP_CHECK_POSITIVE(o, advanced_crf_iterations);
  MSP_CHECK_RANGE(o, advanced_dbscan_eta, 0, core::kMaxKeptAnchors - 1);
  MSP_CHECK_NON_NEGATIVE(o, advanced_dbscan_gamma);
  MSP_CHECK_RANGE(o, advanced_sampling_solutions, 1, core::kMaxSamplingSolutions);
  MSP_CHECK_RANGE(o, advanced_disparity_samples, 1, core::kMaxDisparitySamples);
  if (o.advanced_disparity_samples % 2 == 0) {
    Fail(MSP_OPTION_NAME(o, advanced_disparity_samples), ToText(o.advanced_disparity_samples),
         "odd (the profile is centred on the current disparity)");
  }
  MSP_CHECK_POSITIVE(o, advanced_disparity_step);
  MSP_CHECK_NON_NEGATIVE(o, advanced_variance_weight);
}

void CheckStereoCommandOptions(const StereoCommandOptions& o) {
  if (o.workspace_path.empty()) {
    throw OptionError("missing required option " + MSP_OPTION_FLAG(o, workspace_path));
  }
  MSP_CHECK_ONE_OF(o, workspace_format, "COLMAP", "PMVS");
  MSP_CHECK_NON_NEGATIVE(o, random_seed);
  CheckPatchMatchStereoOptions(o.patch_match);
  CheckMspStereoOptions(o.msp);
}

}  // namespace msp
