// The colours of the map previews, pixel by pixel: depth on the Turbo
// colormap, normals as RGB, and the classes of a depth's error against the
// ground truth. Black always means "nothing here" (no depth, no ground truth).
#pragma once

#include "io/preview_image.h"

namespace msp {

// Turbo (A. Mikhailov, Google, 2019), a rainbow with smooth perceived
// lightness: 0 dark blue, 0.5 green-yellow, 1 dark red; t clamped to [0, 1].
Rgb TurboColor(float t);

// The depths a preview spreads its colours over.
struct DepthRange {
  float near = 0.0f;
  float far = 0.0f;
};

// Near is red, far is blue (Turbo from 1 down to kFarTurbo), depths outside
// the range take the colour of its end; black where `depth` is not a depth
// (0, negative or not finite). A range with near >= far shows green.
Rgb DepthColor(float depth, const DepthRange& range);

// A unit camera-frame normal as ((n + 1) / 2) -> RGB: x right is red, y down
// green, z away from the camera blue; a zero normal (no depth) is black.
Rgb NormalColor(float x, float y, float z);

// Where a map's depth lies against the ground truth, with the evaluator's two
// relative thresholds (msp_evaluate's acc1 / acc2, default 1 % and 5 %).
enum class DepthErrorClass {
  kNoGroundTruth,  // black: the ground truth has no depth here
  kOnEmpty,        // magenta: nothing is there (sky), yet the map has a depth
  kMissing,        // grey: the ground truth has one, the map none
  kAccurate,       // green: |d - gt| / gt <= thresholds[0]
  kClose,          // yellow: <= thresholds[1]
  kWrong,          // red: beyond thresholds[1]
};

// `zero_is_empty`: a ground-truth depth of 0 means nothing is there
// (GroundTruthInfo::ZeroDepthIsEmpty), so a depth on it is kOnEmpty.
DepthErrorClass ClassifyDepthError(float depth, float gt_depth, const double thresholds[2],
                                   bool zero_is_empty = false);
Rgb DepthErrorColor(DepthErrorClass error_class);

}  // namespace msp
