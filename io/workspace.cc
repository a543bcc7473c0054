// LoadWorkspace: a COLMAP dense workspace -> views and problems, with one
// specific error for every kind of bad input (README, "What it reads and writes").
#include "io/workspace.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/cache_budget.h"
#include "base/log.h"
#include "base/stop_request.h"
#include "io/camera_conversion.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "io/image_loading.h"
#include "io/mask_layers.h"
#include "io/patch_match_config.h"
#include "options/option_name.h"

namespace msp {
namespace {

constexpr char kPatchMatchConfig[] = "patch-match.cfg";
constexpr char kFusionConfig[] = "fusion.cfg";

std::string ToLower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void RequireFolder(const std::string& path, const std::string& what) {
  if (!IsDirectory(path)) {
    throw InputError("workspace folder " + path + " does not exist (" + what +
                     "; the workspace must be the output folder of `colmap image_undistorter "
                     "--output_type COLMAP`)");
  }
}

void CheckLayout(const StereoCommandOptions& options) {
  const std::string& ws = options.workspace_path;
  if (ws.empty()) throw InputError(MSP_OPTION_FLAG(options, workspace_path) + " is required");
  if (!IsDirectory(ws)) throw InputError("workspace " + ws + " does not exist or is not a folder");
  const std::string format = ToLower(options.workspace_format);
  if (format == "pmvs") {
    throw InputError(
        "--workspace_format PMVS is not supported; run `colmap image_undistorter "
        "--output_type COLMAP` and use its output folder with --workspace_format COLMAP");
  }
  if (format != "colmap") {
    throw InputError("unknown --workspace_format `" + options.workspace_format +
                     "` (expected COLMAP)");
  }
  RequireFolder(JoinPaths(ws, "sparse"), "the sparse model");
  RequireFolder(JoinPaths(ws, "images"), "the undistorted images");
  RequireFolder(JoinPaths(ws, "stereo"), "where the depth and normal maps go");
}

// Resolves the config entries to model indices. Missing names are fatal, as
// in COLMAP ("Image with name `x` does not exist"); a reference without
// sources is skipped with a warning.
std::vector<Problem> ResolveProblems(const std::vector<PatchMatchConfigEntry>& entries,
                                     const SparseModel& model, const std::string& cfg_path,
                                     double min_triangulation_angle) {
  std::unordered_map<std::string, int> index_of;
  for (size_t i = 0; i < model.images.size(); ++i) index_of[model.images[i].name] = i;
  const int num_images = static_cast<int>(model.images.size());

  std::vector<int> refs;
  std::vector<int> num_auto(num_images, 0);
  for (const PatchMatchConfigEntry& entry : entries) {
    const auto it = index_of.find(entry.ref_name);
    if (it == index_of.end()) {
      throw InputError(cfg_path + ": Image with name `" + entry.ref_name +
                       "` does not exist in the sparse model");
    }
    refs.push_back(it->second);
    if (entry.kind == PatchMatchConfigEntry::Kind::kAuto) {
      num_auto[it->second] = std::max(num_auto[it->second], entry.num_auto);
    }
  }
  const std::vector<std::vector<int>> auto_sources =
      SelectAutoSourcesBatch(model, num_auto, min_triangulation_angle);

  std::vector<Problem> problems;
  for (size_t e = 0; e < entries.size(); ++e) {
    const PatchMatchConfigEntry& entry = entries[e];
    Problem problem;
    problem.ref = refs[e];
    switch (entry.kind) {
      case PatchMatchConfigEntry::Kind::kAll:
        for (int i = 0; i < num_images; ++i) {
          if (i != problem.ref) problem.srcs.push_back(i);
        }
        break;
      case PatchMatchConfigEntry::Kind::kAuto: {
        const std::vector<int>& ranked = auto_sources[problem.ref];
        const size_t count = std::min(ranked.size(), static_cast<size_t>(entry.num_auto));
        problem.srcs.assign(ranked.begin(), ranked.begin() + count);
        break;
      }
      case PatchMatchConfigEntry::Kind::kList:
        for (const std::string& name : entry.src_names) {
          const auto it = index_of.find(name);
          if (it == index_of.end()) {
            throw InputError(cfg_path + ": source image `" + name + "` of reference `" +
                             entry.ref_name + "`: Image with name `" + name +
                             "` does not exist in the sparse model");
          }
          // A view matched against itself carries no depth information.
          if (it->second == problem.ref) continue;
          if (std::find(problem.srcs.begin(), problem.srcs.end(), it->second) ==
              problem.srcs.end()) {
            problem.srcs.push_back(it->second);
          }
        }
        break;
    }
    if (problem.srcs.empty()) {
      LogWarning("Ignoring reference image " + entry.ref_name +
                 ", because it has no source images.");
      continue;
    }
    problems.push_back(std::move(problem));
  }
  return problems;
}

// With allow_missing_files, problems lose their missing sources (and are
// dropped when the reference or every source is missing); without it, the
// first missing file is fatal.
std::vector<Problem> HandleMissingImages(std::vector<Problem> problems, const Workspace& ws,
                                         bool allow_missing_files) {
  std::vector<int> missing(ws.views.size(), -1);  // -1 unknown, 0 present, 1 missing
  auto is_missing = [&](int view) {
    if (missing[view] < 0) {
      const std::string path = JoinPaths(JoinPaths(ws.path, "images"), ws.views[view].name);
      missing[view] = IsFile(path) ? 0 : 1;
      if (missing[view] && !allow_missing_files) {
        throw InputError("image file " + path + " does not exist (image `" + ws.views[view].name +
                         "` of the sparse model; " +
                         MSP_OPTION_FLAG_OF(PatchMatchStereoOptions, allow_missing_files) +
                         " 1 skips missing images)");
      }
      if (missing[view]) LogWarning("image file " + path + " does not exist; ignoring it");
    }
    return missing[view] == 1;
  };
  std::vector<Problem> kept;
  for (Problem& problem : problems) {
    if (is_missing(problem.ref)) {
      LogWarning("Ignoring reference image " + ws.views[problem.ref].name +
                 ", because its image file is missing.");
      continue;
    }
    problem.srcs.erase(std::remove_if(problem.srcs.begin(), problem.srcs.end(), is_missing),
                       problem.srcs.end());
    if (problem.srcs.empty()) {
      LogWarning("Ignoring reference image " + ws.views[problem.ref].name +
                 ", because none of its source images exists.");
      continue;
    }
    kept.push_back(std::move(problem));
  }
  return kept;
}

void AssignDepthRanges(const PatchMatchStereoOptions& options, bool from_sources,
                       const Workspace& ws, std::vector<Problem>* problems) {
  if (options.depth_min > 0.0 && options.depth_max > 0.0) {
    if (options.depth_min >= options.depth_max) {
      throw InputError(MSP_OPTION_FLAG(options, depth_min) + " (" +
                       std::to_string(options.depth_min) + ") must be smaller than " +
                       MSP_OPTION_FLAG(options, depth_max) + " (" +
                       std::to_string(options.depth_max) + ")");
    }
    for (Problem& problem : *problems) {
      problem.depth_min = static_cast<float>(options.depth_min);
      problem.depth_max = static_cast<float>(options.depth_max);
    }
    return;
  }
  // Per image (COLMAP's rule), or per problem with its sources' points.
  const std::vector<std::pair<double, double>> ranges =
      from_sources ? ComputeSharedDepthRanges(ws.model, *problems) : ComputeDepthRanges(ws.model);
  for (size_t p = 0; p < problems->size(); ++p) {
    Problem& problem = (*problems)[p];
    const auto& range = ranges[from_sources ? p : problem.ref];
    if (!(range.first > 0.0 && range.second > 0.0)) {
      throw InputError("no depth range: set " + MSP_OPTION_FLAG(options, depth_min) + " and " +
                       MSP_OPTION_FLAG(options, depth_max) +
                       " (the sparse model has no points observed by " +
                       ws.views[problem.ref].name + ")");
    }
    problem.depth_min = static_cast<float>(range.first);
    problem.depth_max = static_cast<float>(range.second);
  }
}

// The sparse model's points and 2D observations have given the problems and
// depth ranges; nothing reads them after, and they grow with the image count,
// so their memory goes back before the images are read (README, "Memory").
void DropObservations(SparseModel* model) {
  for (SparseImage& image : model->images) std::vector<Point2D>().swap(image.points2D);
  std::vector<SparsePoint3D>().swap(model->points3D);
}

// Cameras of every view at the working resolution; images of used views.
// Every used image is read here, so that a bad one stops the run before it
// starts, but only those within `image_budget_bytes` stay in memory; the
// others are read again by View::load_images when a problem needs them. An
// image at its own size keeps its grey plane (4 bytes a pixel), which every
// problem it is in reads, and its decoded 8-bit pixels (3) for the colour
// plane (12), which only the problems it is the reference of read, and
// load_images converts; a downsized one keeps both planes, which its 8-bit
// pixels cannot give.
void LoadViews(const std::vector<Problem>& problems, int max_image_size, size_t image_budget_bytes,
               Workspace* ws) {
  size_t kept_bytes = 0;
  std::vector<bool> used(ws->views.size(), false);
  for (const Problem& problem : problems) {
    used[problem.ref] = true;
    for (int src : problem.srcs) used[src] = true;
  }
  for (size_t i = 0; i < ws->views.size(); ++i) {
    const SparseImage& image = ws->model.images[i];
    const SparseCamera& camera = ws->model.cameras[ws->model.FindCamera(image.camera_id)];
    View& view = ws->views[i];
    const PinholeCheck check = CheckPinholeCamera(camera, image, nullptr);
    if (!check.ok) {
      // Unused views keep their pose only; a used one cannot be matched.
      if (used[i]) throw InputError(check.message);
      view.camera = MakePoseOnlyCamera(image);
      continue;
    }
    view.camera = MakeCoreCamera(camera, image);
    const int width = view.camera.width;
    const int height = view.camera.height;
    int new_width, new_height;
    DownsizedSize(width, height, max_image_size, &new_width, &new_height);
    ResizeCamera(new_width, new_height, &view.camera);
    if (!used[i]) continue;
    // Reading hundreds of images takes a while: Ctrl-C need not wait for it.
    ThrowIfStopRequested();
    const std::string path = JoinPaths(JoinPaths(ws->path, "images"), view.name);
    view.load_images = [path, width, height, new_width, new_height](DenseMap* gray,
                                                                    DenseMap* color) {
      LoadViewImage(path, width, height, new_width, new_height, gray, color);
    };
    auto decoded = std::make_shared<const DecodedImage>(DecodeViewImage(path, width, height));
    const bool downsized = new_width != width || new_height != height;
    const size_t pixels = static_cast<size_t>(new_width) * new_height;
    const size_t bytes = downsized ? 16 * pixels : 4 * pixels + decoded->bgr.size();
    if (kept_bytes + bytes > image_budget_bytes) continue;
    kept_bytes += bytes;
    if (downsized) {
      ConvertViewImage(*decoded, new_width, new_height, &view.gray, &view.color);
    } else {
      ConvertViewImage(*decoded, new_width, new_height, &view.gray, nullptr);
      view.load_images = [decoded](DenseMap* gray, DenseMap* color) {
        ConvertViewImage(*decoded, decoded->width, decoded->height, gray, color);
      };
    }
  }
}

// The segmentation prior's mask layers of every reference view, read at the
// working resolution; views without mask files are left to the embedded
// segmenter. The prior runs with deformable patches and bounds the matching
// windows, the segment planes and the consensus planes, so nothing is read
// without one of them.
void LoadPriorMaskLayers(const StereoCommandOptions& options, Workspace* ws) {
  if (!options.msp.segmentation_prior ||
      !(options.msp.deformable || options.msp.region_windows || options.msp.segment_planes ||
        options.msp.consensus_planes)) {
    return;
  }
  std::vector<int> refs;
  for (const Problem& problem : ws->problems) {
    if (std::find(refs.begin(), refs.end(), problem.ref) == refs.end()) refs.push_back(problem.ref);
  }
  std::vector<MaskImage> images;
  for (int ref : refs) {
    const SparseImage& image = ws->model.images[ref];
    const SparseCamera& camera = ws->model.cameras[ws->model.FindCamera(image.camera_id)];
    MaskImage mask;
    mask.name = ws->views[ref].name;
    mask.width = static_cast<int>(camera.width);
    mask.height = static_cast<int>(camera.height);
    mask.work_width = ws->views[ref].camera.width;
    mask.work_height = ws->views[ref].camera.height;
    images.push_back(mask);
  }
  // The loader's lines go to the log once it is done (a few lines in all).
  std::ostringstream mask_log;
  std::vector<ImageLabelLayers> layers =
      LoadMaskLayers(ResolveMaskPath(options.msp.mask_path, ws->path), images,
                     options.msp.advanced_num_mask_levels, &mask_log);
  LogText(kLogAlways, mask_log.str());
  for (size_t i = 0; i < refs.size(); ++i) ws->views[refs[i]].mask_layers = std::move(layers[i]);
}

}  // namespace

Workspace LoadWorkspace(const StereoCommandOptions& options) {
  CheckLayout(options);
  Workspace ws;
  ws.path = options.workspace_path;
  ws.model = ReadSparseModel(JoinPaths(ws.path, "sparse"));
  ws.views.resize(ws.model.images.size());
  for (size_t i = 0; i < ws.views.size(); ++i) ws.views[i].name = ws.model.images[i].name;

  const std::string cfg_path = options.config_path.empty()
                                   ? JoinPaths(JoinPaths(ws.path, "stereo"), kPatchMatchConfig)
                                   : options.config_path;
  std::vector<Problem> problems =
      ResolveProblems(ParsePatchMatchConfig(cfg_path), ws.model, cfg_path,
                      options.patch_match.min_triangulation_angle);
  problems = HandleMissingImages(std::move(problems), ws, options.patch_match.allow_missing_files);
  AssignDepthRanges(options.patch_match, options.msp.depth_range_from_sources, ws, &problems);
  DropObservations(&ws.model);
  LoadViews(problems, options.patch_match.max_image_size,
            SplitCacheSize(options.patch_match.cache_size).image_bytes, &ws);
  ws.problems = std::move(problems);
  LoadPriorMaskLayers(options, &ws);
  return ws;
}

std::string DepthMapPath(const std::string& workspace_path, const std::string& image_name,
                         const std::string& type) {
  return JoinPaths(workspace_path, "stereo/depth_maps/" + image_name + "." + type + ".bin");
}

std::string NormalMapPath(const std::string& workspace_path, const std::string& image_name,
                          const std::string& type) {
  return JoinPaths(workspace_path, "stereo/normal_maps/" + image_name + "." + type + ".bin");
}

void WriteFusionConfigIfMissing(const Workspace& workspace) {
  const std::string path = JoinPaths(JoinPaths(workspace.path, "stereo"), kFusionConfig);
  if (IsFile(path)) return;
  std::string text;
  for (const Problem& problem : workspace.problems) {
    text += workspace.views[problem.ref].name + "\n";
  }
  WriteFileAtomic(path, text);
}

}  // namespace msp
