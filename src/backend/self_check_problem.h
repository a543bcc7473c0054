// The problem of the device self-check (device_self_check.h): a textured,
// slightly tilted plane seen by a small reference view and two sources, as a
// pass's PassParams over a caller's pixel state. Small enough for the CPU to
// solve in a fraction of a second at start-up, textured enough that every
// step of a pass has pixels to decide on.
#pragma once

#include <vector>

#include "core/patch_match/patch_match_kernel.h"
#include "engine/pixel_state.h"

namespace msp {

class SelfCheckProblem {
 public:
  SelfCheckProblem();
  SelfCheckProblem(const SelfCheckProblem&) = delete;
  SelfCheckProblem& operator=(const SelfCheckProblem&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // An empty state (no plane yet) of the reference's size.
  PixelState EmptyState() const { return PixelState(width_, height_); }
  // The PassParams of a photometric or, with `geometric`, a geometric pass
  // (the sources' depth maps are the plane's) over `state`, which must be of
  // the reference's size and outlive them, as this problem must.
  core::PassParams Params(bool geometric, PixelState* state) const;

 private:
  int width_, height_;
  std::vector<core::Camera> cameras_;            // the reference first
  std::vector<std::vector<float>> images_;       // grey, one per camera
  std::vector<std::vector<float>> plane_depth_;  // the plane's depth in each camera
};

}  // namespace msp
