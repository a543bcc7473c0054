#include "tools/scene/generate.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tools/scene/parallel.h"
#include "tools/scene/renderer.h"
#include "tools/scene/scene.h"
#include "tools/scene/scene_writer.h"
#include "tools/scene/street_scene.h"
#include "tools/scene/surface_ids.h"
#include "tools/scene/surface_sample.h"
#include "tools/scene/tracks.h"

namespace msp {
namespace scene {
namespace {

// Below this size the 11x11 matching windows of the stereo method dominate
// the image; above it generation stops being "a few seconds".
constexpr int kMinImageSide = 64;
constexpr int kMaxImageSide = 4096;
// Fewer than 2 views cannot triangulate; the rig's arc is designed for ~10,
// and up to 128 make the many-image workspaces of the memory test.
constexpr int kMinCameras = 2;
constexpr int kMaxCameras = 128;
// Depth ranges take percentiles of each image's points: a hundred or more.
constexpr int kMinPoints = 100;
constexpr int kMaxPoints = 100000;

void CheckOptions(const GeneratorOptions& options) {
  const RigOptions& rig = options.rig;
  if (options.output.empty()) throw std::runtime_error("--output is required");
  if (rig.width < kMinImageSide || rig.width > kMaxImageSide || rig.height < kMinImageSide ||
      rig.height > kMaxImageSide) {
    throw std::runtime_error("image size must be within [" + std::to_string(kMinImageSide) + ", " +
                             std::to_string(kMaxImageSide) + "] pixels per side");
  }
  if (options.num_points < kMinPoints || options.num_points > kMaxPoints) {
    throw std::runtime_error("--num_points must be within [" + std::to_string(kMinPoints) + ", " +
                             std::to_string(kMaxPoints) + "]");
  }
  if (rig.num_cameras < kMinCameras || rig.num_cameras > kMaxCameras) {
    throw std::runtime_error("--num_cameras must be within [" + std::to_string(kMinCameras) + ", " +
                             std::to_string(kMaxCameras) + "]");
  }
}

SkyKind ParseSky(const std::string& name) {
  if (name == "pale") return SkyKind::kPale;
  if (name == "blue") return SkyKind::kBlue;
  if (name == "overcast") return SkyKind::kOvercast;
  if (name == "clouds") return SkyKind::kClouds;
  throw std::runtime_error("unknown sky '" + name + "' (pale, blue, overcast, clouds)");
}

bool IsRoom(const GeneratorOptions& options) {
  if (options.kind == "room") return true;
  if (options.kind == "street") return false;
  throw std::runtime_error("unknown scene kind '" + options.kind + "' (room, street)");
}

Scene MakeScene(const GeneratorOptions& options) {
  if (IsRoom(options)) {
    Scene scene = MakeRoomScene(options.sky_window);
    if (!options.sky.empty()) scene.sky = ParseSky(options.sky);
    return scene;
  }
  return MakeStreetScene(ParseSky(options.sky.empty() ? "blue" : options.sky));
}

// scene.json's header: the bundled scene's as it always was (its files stay
// byte for byte the same), the kind and sky added for any other.
std::vector<std::pair<std::string, std::string>> JsonHeader(const GeneratorOptions& options) {
  std::vector<std::pair<std::string, std::string>> header = {
      {"seed", std::to_string(options.seed)},
      {"sky_window", options.sky_window ? "true" : "false"}};
  if (!IsRoom(options) || !options.sky.empty()) {
    header.push_back({"kind", options.kind});
    header.push_back({"sky", options.sky.empty() ? "blue" : options.sky});
  }
  return header;
}

}  // namespace

GeneratorSummary GenerateScene(const GeneratorOptions& options) {
  CheckOptions(options);
  const Scene scene = MakeScene(options);
  const std::vector<PinholeView> views =
      MakeCameraRig(IsRoom(options) ? options.rig : StreetRig(options.rig), options.seed);
  std::vector<RenderedView> rendered(views.size());
  ParallelIndices(static_cast<int>(views.size()),
                  [&](int i) { rendered[i] = RenderView(scene, views[i], i, options.seed); });
  TrackOptions tracks;
  tracks.num_points = options.num_points;
  const SparseModel model = BuildSparseModel(scene, views, tracks, options.seed);
  const SurfaceSample sample = SampleVisibleSurface(scene, views, rendered);

  WriteColmapWorkspace(options.output, model, rendered);
  WriteGroundTruth(options.output, views, rendered, sample,
                   GroundTruthJson(views, sample, JsonHeader(options)));
  if (options.ideal_masks) {
    std::vector<IdealMasks> masks(views.size());
    ParallelIndices(static_cast<int>(views.size()),
                    [&](int i) { masks[i] = RenderIdealMasks(scene, views[i]); });
    WriteIdealMasks(options.output, views, masks);
  }

  GeneratorSummary summary;
  summary.num_images = static_cast<int>(views.size());
  summary.num_points3D = static_cast<int>(model.points3D.size());
  size_t observations = 0;
  for (const SparsePoint3D& p : model.points3D) observations += p.track.size();
  summary.mean_track_length =
      model.points3D.empty() ? 0.0 : static_cast<double>(observations) / model.points3D.size();
  summary.num_surface_samples = static_cast<int>(sample.points.size());
  summary.extent = sample.Extent();
  return summary;
}

}  // namespace scene
}  // namespace msp
