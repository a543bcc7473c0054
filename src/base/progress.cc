#include "base/progress.h"

#include <cmath>
#include <cstdio>
#include <utility>

namespace msp {
namespace {

ProgressListener progress_listener;  // empty = none

}  // namespace

double EstimateSecondsLeft(double done_weight, double total_weight, double elapsed_seconds) {
  if (done_weight <= 0) return -1;
  const double left = total_weight > done_weight ? total_weight - done_weight : 0.0;
  return elapsed_seconds / done_weight * left;
}

std::string FormatDuration(double seconds) {
  if (seconds < 0 || !std::isfinite(seconds)) return "?";
  char text[32];
  const long s = std::lround(seconds);
  if (s < 60) {
    std::snprintf(text, sizeof(text), "%lds", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof(text), "%ldm%02lds", s / 60, s % 60);
  } else {
    const long m = std::lround(seconds / 60.0);
    std::snprintf(text, sizeof(text), "%ldh%02ldm", m / 60, m % 60);
  }
  return text;
}

ProgressMeter::ProgressMeter(int total_items, double total_weight)
    : total_items_(total_items), total_weight_(total_weight) {}

void ProgressMeter::Add(double weight) {
  ++done_items_;
  done_weight_ += weight;
}

std::string ProgressMeter::Line(double elapsed_seconds) const {
  const double share = total_weight_ > 0 ? 100.0 * done_weight_ / total_weight_ : 100.0;
  char text[160];
  std::snprintf(
      text, sizeof(text), "progress %d/%d image-passes (%.1f%% of the work), elapsed %s, ETA %s",
      done_items_, total_items_, share, FormatDuration(elapsed_seconds).c_str(),
      FormatDuration(EstimateSecondsLeft(done_weight_, total_weight_, elapsed_seconds)).c_str());
  return text;
}

void SetProgressListener(ProgressListener listener) { progress_listener = std::move(listener); }

void ReportProgress(const ProgressMeter& meter, double elapsed_seconds) {
  if (!progress_listener) return;
  ProgressUpdate update;
  update.done = meter.done_items();
  update.total = meter.total_items();
  update.elapsed_seconds = elapsed_seconds;
  update.seconds_left =
      EstimateSecondsLeft(meter.done_weight(), meter.total_weight(), elapsed_seconds);
  progress_listener(update);
}

}  // namespace msp
