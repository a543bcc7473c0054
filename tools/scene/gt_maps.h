// Writes the ground-truth depth and normal maps into a workspace's stereo/
// folder as if a stereo method had produced them: the exact oracle for the
// COLMAP contract (fused by `colmap stereo_fusion`, the result must lie on
// the true surfaces). A depth scale != 1 simulates a systematically wrong
// method, which the contract test must catch.
#pragma once

#include <string>

namespace msp {
namespace scene {

struct GroundTruthMapOptions {
  std::string workspace;
  std::string ground_truth;              // default <workspace>/ground_truth
  std::string input_type = "geometric";  // suffix: geometric | photometric
  double depth_scale = 1.0;
};

// Returns the number of images written. Throws InputError on bad input.
int WriteGroundTruthMaps(const GroundTruthMapOptions& options);

}  // namespace scene
}  // namespace msp
