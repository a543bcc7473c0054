// What a back-end's deformable step (SweepEngine::DeformableIterations) takes
// and gives: every pixel's reliability class with its nearest reliable pixel,
// the anchor search's and the cost's settings, and the step's figures. The
// CPU's step is deformable/deformable_sweeps.h, the device's backend/cuda/.
#pragma once

#include <cstdint>
#include <vector>

#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/synergistic_optimization.h"

namespace msp {

struct ReliabilityMaps {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> classes;  // core::kReliable / kUnreliable / kUnknown
  std::vector<int> nearest;      // nearest reliable pixel index, -1 = none
  int num_reliable = 0;
  int num_unreliable = 0;
};

struct DeformableSettings {
  core::AnchorParams anchors;
  core::DeformableParams cost;
  // Depth edges of the segmentation prior that confine the anchor search
  // (1 byte per pixel, nonzero = edge); data == nullptr = unconfined.
  core::BoundaryView edges{nullptr, 0, 0, 0};
  // The nearest edge pixel of every pixel (NearestMarkedPixels of the edges),
  // or nullptr: lets the search skip walks that cannot reach an edge.
  const int* nearest_edge = nullptr;
  // Disparity-sampling synergistic 3D optimization (core/deformable/
  // synergistic_optimization.h): random sampling solutions, optimized in
  // the first `synergy_iterations` iterations of the pass; false = the fixed grid.
  bool synergistic = false;
  core::SynergyParams synergy = core::DefaultSynergyParams();
  int synergy_iterations = 1;
};

// Statistics of one call, for the log.
struct DeformableStats {
  long long anchored_updates = 0;  // deformable pixel updates over all iterations
  double anchor_seconds = 0.0;     // wall time of the anchor searches
  double sweep_seconds = 0.0;      // wall time of the red-black sweeps
};

}  // namespace msp
