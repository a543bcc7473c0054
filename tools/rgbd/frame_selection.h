// Which frames of a sequence become the workspace's images: index ranges,
// every k-th of those, and a minimum baseline. Video runs at 30 frames a
// second: neighbours are nearly the same view, so a benchmark takes a few
// frames with enough baseline to triangulate and enough overlap to match.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace msp {
namespace rgbd {

struct FrameSelection {
  // Index ranges in sorted image order, inclusive, 0-based: "0-8,35-39",
  // "12", "" = every frame. Ranges must not overlap and must be ascending.
  std::string frames;
  int step = 1;               // every step-th frame of the ranges, from each range's first
  double min_baseline = 0.0;  // metres between a kept frame and the previous kept one
};

// Fewer views cannot triangulate a track.
constexpr int kMinSelectedFrames = 2;

// The selected indices into `centers` (camera centres in sorted order), in
// order. Throws InputError naming the option for a malformed or out-of-range
// --frames, a step below 1, a negative baseline or fewer than
// kMinSelectedFrames frames left.
std::vector<int> SelectFrames(const std::vector<Eigen::Vector3d>& centers,
                              const FrameSelection& selection);

}  // namespace rgbd
}  // namespace msp
