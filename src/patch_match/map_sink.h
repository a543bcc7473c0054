// Where the pass runner hands finished maps (io/map_writer.h writes them as
// COLMAP files).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/dense_map.h"

namespace msp {

// The type of a view's final maps, as COLMAP names them: "geometric" with
// --PatchMatchStereo.geom_consistency (the filtered maps of the geometric
// passes), else "photometric".
inline const char* FinalMapType(bool geom_consistency) {
  return geom_consistency ? "geometric" : "photometric";
}

class MapSink {
 public:
  virtual ~MapSink() = default;
  // True when the final outputs for view `view` already exist, so its problem
  // is skipped (resume, as COLMAP does).
  virtual bool HasFinalOutput(int view) const = 0;
  // `type` is "photometric" or "geometric". depth: 1 channel, 0 = invalid;
  // normal: 3 channels, unit, camera frame, (0,0,0) where depth is 0.
  virtual void Write(int view, const std::string& type, const DenseMap& depth,
                     const DenseMap& normal) = 0;
  // With --MspStereo.write_previews: the final pass's image `color` (RGB) and
  // the segmentation prior's aggregated and refined edge maps (0/1, either
  // may be empty) that confined its anchors. A sink that keeps no pictures
  // ignores them.
  virtual void WritePriorPreview(int /*view*/, const DenseMap& /*color*/,
                                 const std::vector<uint8_t>& /*aggregated_edges*/,
                                 const std::vector<uint8_t>& /*refined_edges*/) {}
  // With --MspStereo.write_previews: the final maps of `view`, the same that
  // Write receives next, to draw as pictures (with or without the prior).
  // Called before Write, so that a view whose final maps exist has its
  // pictures too. A sink that keeps no pictures ignores them.
  virtual void WriteMapPreviews(int /*view*/, const DenseMap& /*depth*/,
                                const DenseMap& /*normal*/) {}
  // With --MspStereo.write_previews: where each pixel's depth went (ExtractMaps'
  // stages map: core::MapStage and the depth before the filter). A sink that
  // keeps no pictures ignores it.
  virtual void WriteStagesMap(int /*view*/, const DenseMap& /*stages*/) {}
};

}  // namespace msp
