// The sparse model of the scene: cameras, poses and real point tracks, as
// COLMAP's image_undistorter would leave them after SfM. Tracks matter: they
// give patch_match's __auto__ source selection and depth ranges, and
// stereo_fusion's image-overlap graph.
#pragma once

#include <cstdint>
#include <vector>

#include "io/sparse_model.h"
#include "tools/scene/camera_rig.h"
#include "tools/scene/scene.h"

namespace msp {
namespace scene {

struct TrackOptions {
  // Target number of 3D points (each with a track of length >= 2).
  int num_points = 6000;
  // Surface samples tried before giving up on the target.
  int max_attempts = 400000;
  // SfM finds features mostly on texture: a sample on a textureless surface
  // is kept with this probability only (textured ones always), so the walls
  // still get a few points, as corner-like features on them would.
  double textureless_acceptance = 0.12;
};

// One PINHOLE camera per view (ids 1..n), images with ids 1..n in view order,
// and points observed in every view where they are visible and in the image.
SparseModel BuildSparseModel(const Scene& scene, const std::vector<PinholeView>& views,
                             const TrackOptions& options, uint64_t seed);

}  // namespace scene
}  // namespace msp
