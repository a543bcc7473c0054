#include "tools/scene/gt_maps.h"

#include "io/dense_map_io.h"
#include "io/errors.h"
#include "io/ground_truth.h"

namespace msp {
namespace scene {

int WriteGroundTruthMaps(const GroundTruthMapOptions& options) {
  if (options.workspace.empty()) throw InputError("--workspace is required");
  if (!(options.depth_scale > 0.0)) throw InputError("--scale must be positive");
  if (options.input_type != "geometric" && options.input_type != "photometric") {
    throw InputError("--input_type must be geometric or photometric, not " + options.input_type);
  }
  const GroundTruthInfo info =
      ReadGroundTruthInfo(GroundTruthDir(options.workspace, options.ground_truth));
  for (const std::string& name : info.image_names) {
    DenseMap depth = ReadDenseMap(info.DepthMapPath(name));
    for (float& d : depth.data) d = static_cast<float>(d * options.depth_scale);
    const std::string suffix = name + "." + options.input_type + ".bin";
    WriteDenseMap(options.workspace + "/stereo/depth_maps/" + suffix, depth);
    WriteDenseMap(options.workspace + "/stereo/normal_maps/" + suffix,
                  ReadDenseMap(info.NormalMapPath(name)));
  }
  return static_cast<int>(info.image_names.size());
}

}  // namespace scene
}  // namespace msp
