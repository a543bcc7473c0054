// The stages a pixel's depth passes between the last pass and the written
// maps, as the stages map of --MspStereo.write_previews records them.
#pragma once

namespace msp {
namespace core {

// Where a pixel's depth goes between the last pass and the written maps: the
// codes of the stages map that --MspStereo.write_previews writes
// (docs/method.md section 2.9), so that lost surface can be measured.
enum MapStage : int {
  kStageKept = 1,               // in the maps
  kStageNoPlane = 2,            // the last pass left no plane (unlit, never found, out of range)
  kStageOpenSky = 3,            // open sky (section 2.11)
  kStageFilterAngle = 4,        // the filter: would pass without the triangulation-angle test
  kStageFilterPhotometric = 5,  // ... without the NCC test
  kStageFilterGeometric = 6,    // ... without the geometric test (depth agreement)
  kStageFilterSeveral = 7,      // ... needs more than one test dropped, or has too few views
};

}  // namespace core
}  // namespace msp
