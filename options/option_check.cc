#include "options/option_check.h"

#include <sstream>
#include <string>

#include "core/deformable/anchors.h"
#include "core/prior/prior_limits.h"

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

// Interval checks; `lo_open`/`hi_open` exclude the bound, as in "[0, 180)".
template <typename T>
void CheckRange(const std::string& option, T value, T lo, T hi, bool lo_open = false,
                bool hi_open = false, const std::string& why = "") {
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

const std::string kPm = "PatchMatchStereo.";

void CheckDepthRange(const PatchMatchStereoOptions& o) {
  // COLMAP: both -1 = per-image range from the sparse model; otherwise a
  // manual range with 0 <= min <= max.
  if (o.depth_min == -1.0 && o.depth_max == -1.0) return;
  const std::string allowed_min =
      "-1 (automatic, with depth_max -1) or in [0, depth_max = " + ToText(o.depth_max) + "]";
  if (!(o.depth_min >= 0.0)) Fail(kPm + "depth_min", ToText(o.depth_min), allowed_min);
  if (!(o.depth_max >= o.depth_min)) {
    Fail(kPm + "depth_max", ToText(o.depth_max),
         "-1 (automatic, with depth_min -1) or >= depth_min = " + ToText(o.depth_min));
  }
}

}  // namespace

void CheckPatchMatchStereoOptions(const PatchMatchStereoOptions& o) {
  CheckDepthRange(o);
  CheckRange(kPm + "window_radius", o.window_radius, 1, kMaxWindowRadius, false, false,
             " (the widest window the back-ends hold, kMaxWindowRadius; COLMAP allows 32)");
  CheckRange(kPm + "window_step", o.window_step, 1, 2);
  CheckPositive(kPm + "sigma_color", o.sigma_color);
  CheckPositive(kPm + "num_samples", o.num_samples);
  CheckPositive(kPm + "ncc_sigma", o.ncc_sigma);
  CheckRange(kPm + "min_triangulation_angle", o.min_triangulation_angle, 0.0, 180.0, false, true);
  CheckPositive(kPm + "incident_angle_sigma", o.incident_angle_sigma);
  CheckPositive(kPm + "num_iterations", o.num_iterations);
  CheckNonNegative(kPm + "geom_consistency_regularizer", o.geom_consistency_regularizer);
  CheckNonNegative(kPm + "geom_consistency_max_cost", o.geom_consistency_max_cost);
  CheckRange(kPm + "filter_min_ncc", o.filter_min_ncc, -1.0, 1.0);
  CheckRange(kPm + "filter_min_triangulation_angle", o.filter_min_triangulation_angle, 0.0, 180.0);
  CheckNonNegative(kPm + "filter_min_num_consistent", o.filter_min_num_consistent);
  CheckNonNegative(kPm + "filter_geom_consistency_max_cost", o.filter_geom_consistency_max_cost);
  CheckPositive(kPm + "cache_size", o.cache_size);
}

void CheckMspStereoOptions(const MspStereoOptions& o) {
  if (o.backend != "cpu" && o.backend != "cuda") {
    Fail("MspStereo.backend", "`" + o.backend + "`", "one of {cpu, cuda}");
  }
  CheckNonNegative("MspStereo.seed", o.seed);
  CheckRange("MspStereo.coarsest_image_size", o.coarsest_image_size, kMinCoarsestImageSize, 1 << 20,
             false, false, " (smaller images have too few pixels to match)");
  CheckRange("MspStereo.window_step", o.window_step, 1, 2);
  CheckRange("MspStereo.reliable_max_cost", o.reliable_max_cost, 0.0, 2.0);
  CheckRange("MspStereo.reliable_single_cost", o.reliable_single_cost, 0.0, 2.0);
  CheckRange("MspStereo.reliable_min_spread", o.reliable_min_spread, 0.0, 2.0);
  CheckRange("MspStereo.anchor_max_distance", o.anchor_max_distance, core::kFirstRayRadius, 1 << 16,
             false, false, " (the first ray sample lies 2 px from the pixel)");
  CheckRange("MspStereo.num_mask_levels", o.num_mask_levels, 1, core::kMaxLabelLayers, false, false,
             " (best-layer sets are 32-bit sets, kMaxLabelLayers)");
  CheckPositive("MspStereo.crf_alpha", o.crf_alpha);
  CheckPositive("MspStereo.crf_beta", o.crf_beta);
  CheckRange("MspStereo.crf_unary_confidence", o.crf_unary_confidence, 0.0, 1.0, true, true);
  CheckPositive("MspStereo.crf_iterations", o.crf_iterations);
}

void CheckStereoCommandOptions(const StereoCommandOptions& o) {
  if (o.workspace_path.empty()) {
    throw OptionError("missing required option --workspace_path");
  }
  if (o.workspace_format != "COLMAP" && o.workspace_format != "PMVS") {
    Fail("workspace_format", "`" + o.workspace_format + "`", "one of {COLMAP, PMVS}");
  }
  CheckPatchMatchStereoOptions(o.patch_match);
  CheckMspStereoOptions(o.msp);
}

}  // namespace msp
