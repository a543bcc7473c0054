// The MapSink of the msp_stereo command: finished maps become COLMAP files
// under <workspace>/stereo/{depth,normal}_maps/<name>.<type>.bin.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/ground_truth.h"
#include "patch_match/map_sink.h"

namespace msp {

class MapWriter : public MapSink {
 public:
  // `view_names[i]` is the image name of view i. The final output type is
  // FinalMapType(geom_consistency), the runner's. With `ground_truth` (the bundled scene's),
  // the map previews include error previews of the images it lists.
  MapWriter(std::string workspace_path, std::vector<std::string> view_names, bool geom_consistency,
            std::optional<GroundTruthInfo> ground_truth = std::nullopt);

  // True when both final files (depth and normal) exist. Consistency graphs
  // are not required: nothing in COLMAP reads them.
  bool HasFinalOutput(int view) const override;

  // Writes the depth map, then the normal map, each atomically. Throws
  // std::invalid_argument for a bad view index, type or map shape (a back-end
  // bug) and InputError when a file cannot be written. Holds no mutable
  // state, so back-ends may call it from several threads for different views.
  void Write(int view, const std::string& type, const DenseMap& depth,
             const DenseMap& normal) override;

  // <workspace>/stereo/prior_previews/<name>.png (prior_previews.h),
  // atomically; InputError when it cannot be written.
  void WritePriorPreview(int view, const DenseMap& color,
                         const std::vector<uint8_t>& aggregated_edges,
                         const std::vector<uint8_t>& refined_edges) override;

  // <workspace>/stereo/prior_previews/<name>.{depth,normal,error}.png
  // (map_previews.h), each atomically; std::invalid_argument for maps Write
  // would reject, InputError when a file cannot be read or written.
  void WriteMapPreviews(int view, const DenseMap& depth, const DenseMap& normal) override;
  void WriteStagesMap(int view, const DenseMap& stages) override;

  const std::string& final_type() const { return final_type_; }

 private:
  const std::string& Name(int view) const;

  std::string workspace_path_;
  std::vector<std::string> view_names_;
  std::string final_type_;
  std::optional<GroundTruthInfo> ground_truth_;
};

}  // namespace msp
