// The whole scene generation: render every view, build the sparse model and
// the surface sample, write the workspace and the ground truth.
#pragma once

#include <cstdint>
#include <string>

#include "tools/scene/camera_rig.h"

namespace msp {
namespace scene {

struct GeneratorOptions {
  std::string output;  // workspace folder (created)
  uint64_t seed = 1;
  RigOptions rig;
  // Target number of sparse points (TrackOptions::num_points); fewer make a
  // small model for the many-image workspaces of the memory test.
  int num_points = 6000;
  // The scene: "room" (MakeRoomScene, the bundled scene) or "street"
  // (MakeStreetScene: open sky reaching the views' borders).
  std::string kind = "room";
  // The sky (SkyKind): "pale" (the bundled scene's), "blue", "overcast",
  // "clouds"; empty: the kind's own (room: pale, street: blue).
  std::string sky;
  // The window to the sky in the y = 0 wall (MakeRoomScene).
  bool sky_window = true;
  // Also write masks/<name>.<level>.png: the ideal mask layers of every view
  // (surface_ids.h). Nothing else changes.
  bool ideal_masks = false;
};

struct GeneratorSummary {
  int num_images = 0;
  int num_points3D = 0;
  double mean_track_length = 0.0;
  int num_surface_samples = 0;
  double extent = 0.0;
};

// Throws std::runtime_error / InputError on invalid options or I/O failure.
GeneratorSummary GenerateScene(const GeneratorOptions& options);

}  // namespace scene
}  // namespace msp
