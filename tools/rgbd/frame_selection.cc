#include "tools/rgbd/frame_selection.h"

#include <sstream>

#include "io/errors.h"

namespace msp {
namespace rgbd {
namespace {

// "A-B" or "A": false when malformed.
bool ParseRange(const std::string& text, int* first, int* last) {
  std::istringstream in(text);
  char dash = 0;
  if (!(in >> *first)) return false;
  *last = *first;
  if (in >> dash) {
    if (dash != '-' || !(in >> *last)) return false;
  }
  std::string rest;
  return !(in >> rest);
}

std::vector<int> RangeIndices(const std::string& frames, int num_frames, int step) {
  std::vector<int> indices;
  if (frames.empty()) {
    for (int i = 0; i < num_frames; i += step) indices.push_back(i);
    return indices;
  }
  std::istringstream list(frames);
  int previous_last = -1;
  for (std::string range; std::getline(list, range, ',');) {
    int first = 0, last = 0;
    if (!ParseRange(range, &first, &last) || first < 0 || last < first) {
      throw InputError("--frames: `" + range + "` is not a range A-B with 0 <= A <= B");
    }
    if (last >= num_frames) {
      throw InputError("--frames: `" + range + "` reaches past the last frame, " +
                       std::to_string(num_frames - 1));
    }
    if (first <= previous_last) {
      throw InputError("--frames: `" + range + "` overlaps or precedes the range before it");
    }
    for (int i = first; i <= last; i += step) indices.push_back(i);
    previous_last = last;
  }
  return indices;
}

}  // namespace

std::vector<int> SelectFrames(const std::vector<Eigen::Vector3d>& centers,
                              const FrameSelection& selection) {
  if (selection.step < 1) {
    throw InputError("--step must be at least 1, not " + std::to_string(selection.step));
  }
  if (!(selection.min_baseline >= 0.0)) {
    throw InputError("--min_baseline must not be negative");
  }
  const int n = static_cast<int>(centers.size());
  std::vector<int> selected;
  for (const int i : RangeIndices(selection.frames, n, selection.step)) {
    if (!selected.empty() &&
        (centers[i] - centers[selected.back()]).norm() < selection.min_baseline) {
      continue;
    }
    selected.push_back(i);
  }
  if (static_cast<int>(selected.size()) < kMinSelectedFrames) {
    throw InputError("the frame selection (--frames, --step, --min_baseline) keeps " +
                     std::to_string(selected.size()) + " of " + std::to_string(n) +
                     " frames; at least " + std::to_string(kMinSelectedFrames) + " are needed");
  }
  return selected;
}

}  // namespace rgbd
}  // namespace msp
