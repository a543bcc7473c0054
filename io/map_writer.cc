#include "io/map_writer.h"

#include <filesystem>
#include <stdexcept>
#include <utility>

#include "io/dense_map_io.h"
#include "io/map_previews.h"
#include "io/prior_previews.h"
#include "io/workspace.h"

namespace msp {
namespace {

// Throws std::invalid_argument unless depth and normal are 1- and 3-channel
// maps of the same non-zero size (a back-end bug).
void CheckMaps(const std::string& name, const DenseMap& depth, const DenseMap& normal) {
  if (depth.channels != 1 || normal.channels != 3 || depth.width != normal.width ||
      depth.height != normal.height || depth.Empty()) {
    throw std::invalid_argument("MapWriter: depth (" + std::to_string(depth.channels) +
                                " channels) and normal (" + std::to_string(normal.channels) +
                                " channels) maps of " + name + " must be 1- and 3-channel " +
                                "maps of the same non-zero size");
  }
}

}  // namespace

MapWriter::MapWriter(std::string workspace_path, std::vector<std::string> view_names,
                     bool geom_consistency, std::optional<GroundTruthInfo> ground_truth)
    : workspace_path_(std::move(workspace_path)),
      view_names_(std::move(view_names)),
      final_type_(FinalMapType(geom_consistency)),
      ground_truth_(std::move(ground_truth)) {}

const std::string& MapWriter::Name(int view) const {
  if (view < 0 || view >= static_cast<int>(view_names_.size())) {
    throw std::invalid_argument("MapWriter: view index " + std::to_string(view) +
                                " out of range [0, " + std::to_string(view_names_.size()) + ")");
  }
  return view_names_[view];
}

bool MapWriter::HasFinalOutput(int view) const {
  const std::string& name = Name(view);
  std::error_code error;
  return std::filesystem::is_regular_file(DepthMapPath(workspace_path_, name, final_type_),
                                          error) &&
         std::filesystem::is_regular_file(NormalMapPath(workspace_path_, name, final_type_), error);
}

void MapWriter::Write(int view, const std::string& type, const DenseMap& depth,
                      const DenseMap& normal) {
  const std::string& name = Name(view);
  if (type != "photometric" && type != "geometric") {
    throw std::invalid_argument("MapWriter: unknown map type `" + type + "` for " + name);
  }
  CheckMaps(name, depth, normal);
  // Depth first: HasFinalOutput needs both files, so a run interrupted
  // between the two writes recomputes this view instead of skipping it.
  WriteDenseMap(DepthMapPath(workspace_path_, name, type), depth);
  WriteDenseMap(NormalMapPath(workspace_path_, name, type), normal);
}

void MapWriter::WritePriorPreview(int view, const DenseMap& color,
                                  const std::vector<uint8_t>& aggregated_edges,
                                  const std::vector<uint8_t>& refined_edges) {
  msp::WritePriorPreview(PriorPreviewPath(workspace_path_, Name(view)), color, aggregated_edges,
                         refined_edges);
}

void MapWriter::WriteMapPreviews(int view, const DenseMap& depth, const DenseMap& normal) {
  const std::string& name = Name(view);
  CheckMaps(name, depth, normal);
  msp::WriteMapPreviews(workspace_path_, name, depth, normal,
                        ground_truth_ ? &*ground_truth_ : nullptr);
}

void MapWriter::WriteStagesMap(int view, const DenseMap& stages) {
  msp::WriteStagesMap(workspace_path_, Name(view), stages);
}

}  // namespace msp
