#include "io/colormaps.h"

#include <cmath>

namespace msp {
namespace {

// The polynomial fit of Turbo published with it (Apache-2.0, R. Du), degree
// 0 to 5 per channel: a smooth curve, 6 levels of 255 from the original table
// on average and at most 32, at the dark ends.
constexpr float kTurboRed[6] = {0.13572138f,   4.61539260f,    -42.66032258f,
                                132.13108234f, -152.94239396f, 59.28637943f};
constexpr float kTurboGreen[6] = {0.09140261f,   2.19418839f, 4.84296658f,
                                  -14.18503333f, 4.27729857f, 2.82956604f};
constexpr float kTurboBlue[6] = {0.10667330f,   12.64194608f,  -60.58204836f,
                                 110.36276771f, -89.90310912f, 27.34824973f};

// Turbo below this is nearly black, the colour of pixels without depth: the
// far end of the depth range stops here, at a clear blue.
constexpr float kFarTurbo = 0.05f;
// Where near and far coincide (a single depth), the middle of the scale.
constexpr float kMidTurbo = 0.5f;

float Polynomial(const float (&c)[6], float t) {
  return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
}

bool IsDepth(float d) { return std::isfinite(d) && d > 0.0f; }

// The class colours: traffic lights, grey for holes, magenta for a surface
// where nothing is.
constexpr Rgb kAccurateColor{0, 200, 0};
constexpr Rgb kCloseColor{255, 215, 0};
constexpr Rgb kWrongColor{230, 0, 0};
constexpr Rgb kMissingColor{128, 128, 128};
constexpr Rgb kOnEmptyColor{230, 0, 230};

}  // namespace

Rgb TurboColor(float t) {
  t = std::fmin(std::fmax(t, 0.0f), 1.0f);
  return Rgb{ToByte(Polynomial(kTurboRed, t)), ToByte(Polynomial(kTurboGreen, t)),
             ToByte(Polynomial(kTurboBlue, t))};
}

Rgb DepthColor(float depth, const DepthRange& range) {
  if (!IsDepth(depth)) return Rgb{};
  if (!(range.far > range.near)) return TurboColor(kMidTurbo);
  const float nearness = (range.far - depth) / (range.far - range.near);  // 1 = near
  return TurboColor(kFarTurbo + (1.0f - kFarTurbo) * std::fmin(std::fmax(nearness, 0.0f), 1.0f));
}

Rgb NormalColor(float x, float y, float z) {
  if (x == 0.0f && y == 0.0f && z == 0.0f) return Rgb{};
  return Rgb{ToByte(0.5f * (x + 1.0f)), ToByte(0.5f * (y + 1.0f)), ToByte(0.5f * (z + 1.0f))};
}

DepthErrorClass ClassifyDepthError(float depth, float gt_depth, const double thresholds[2],
                                   bool zero_is_empty) {
  // The same tests, in the same precision, as the evaluator's figures.
  if (!(gt_depth > 0.0f)) {
    return zero_is_empty && IsDepth(depth) ? DepthErrorClass::kOnEmpty
                                           : DepthErrorClass::kNoGroundTruth;
  }
  if (!IsDepth(depth)) return DepthErrorClass::kMissing;
  const double relative = std::abs(static_cast<double>(depth) - gt_depth) / gt_depth;
  if (relative <= thresholds[0]) return DepthErrorClass::kAccurate;
  return relative <= thresholds[1] ? DepthErrorClass::kClose : DepthErrorClass::kWrong;
}

Rgb DepthErrorColor(DepthErrorClass error_class) {
  switch (error_class) {
    case DepthErrorClass::kNoGroundTruth:
      break;
    case DepthErrorClass::kOnEmpty:
      return kOnEmptyColor;
    case DepthErrorClass::kMissing:
      return kMissingColor;
    case DepthErrorClass::kAccurate:
      return kAccurateColor;
    case DepthErrorClass::kClose:
      return kCloseColor;
    case DepthErrorClass::kWrong:
      return kWrongColor;
  }
  return Rgb{};
}

}  // namespace msp
