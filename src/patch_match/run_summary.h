// The table a stereo run ends with: where the time went, pass by pass, and
// what each reference image got (its final map's valid pixels).
#pragma once

#include <string>
#include <vector>

namespace msp {

struct PassTime {
  std::string label;  // e.g. "round 2/2, geometric pass 3"
  double seconds = 0;
};

struct ImageOutcome {
  std::string name;
  int width = 0;
  int height = 0;
  // Valid (non-zero depth) pixels of the final map this run wrote; -1 = the
  // image had its final maps from an earlier run and they were kept.
  long valid_pixels = -1;
};

// Two tables, one row per pass (seconds and share of all passes' time) and
// one per image (valid pixels and their share of the map), then the totals.
std::string FormatRunSummary(const std::vector<PassTime>& passes,
                             const std::vector<ImageOutcome>& images);

}  // namespace msp
