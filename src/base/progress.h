// The running total of a stereo run: image-passes done of all, elapsed time
// and the time left, estimated from the measured rate. Image-passes cost
// unequal time (a coarse round's image has a quarter of the pixels of the
// next), so each carries a weight, its pixel count at its pyramid level, and
// the rate is elapsed seconds per unit of weight done so far.
#pragma once

#include <functional>
#include <string>

namespace msp {

// Seconds left when `done_weight` of `total_weight` took `elapsed_seconds`;
// negative when nothing is done yet (no rate measured).
double EstimateSecondsLeft(double done_weight, double total_weight, double elapsed_seconds);

// "45s", "3m07s", "2h05m" (rounded to the unit shown last); "?" for a negative value.
std::string FormatDuration(double seconds);

class ProgressMeter {
 public:
  ProgressMeter(int total_items, double total_weight);

  // One image-pass of weight `weight` finished.
  void Add(double weight);

  int done_items() const { return done_items_; }
  int total_items() const { return total_items_; }
  double done_weight() const { return done_weight_; }
  double total_weight() const { return total_weight_; }

  // "progress 12/48 image-passes (31.2% of the work), elapsed 1m02s, ETA 2m17s"
  std::string Line(double elapsed_seconds) const;

 private:
  int total_items_;
  double total_weight_;
  int done_items_ = 0;
  double done_weight_ = 0;
};

// What a run tells an observer after each image-pass (the Python module's
// progress callback): image-passes done of all, seconds since the first and
// the estimated seconds left (negative when unknown).
struct ProgressUpdate {
  int done = 0;
  int total = 0;
  double elapsed_seconds = 0;
  double seconds_left = -1;
};
using ProgressListener = std::function<void(const ProgressUpdate&)>;

// Replaces the listener; an empty one removes it. Set it while no run is
// under way, as the log sink.
void SetProgressListener(ProgressListener listener);

// Hands `meter`'s totals to the listener, if any, on the calling thread: the
// thread that runs the schedule, between two image-passes, where the run can
// unwind as from a stop request (stop_request.h). A listener may end the run
// there by throwing, e.g. StopRequested.
void ReportProgress(const ProgressMeter& meter, double elapsed_seconds);

}  // namespace msp
