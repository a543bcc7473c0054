// Which plane the matching cost prefers on the pixels a run got wrong: the
// run's own plane or the ground truth's, at any pyramid level. A wrong pixel
// whose true plane costs clearly less is a search failure (propagation,
// anchors or refinement never offered it); one where both cost about the
// same has no photometric evidence either way (only geometry, a prior or a
// fill can decide); one where the truth costs clearly more is matched
// against the evidence (occlusion, a window across a depth edge).
//
//   msp_plane_costs --workspace WS [--halvings H] [--input_type geometric]
//
// The maps and the ground truth are read at the workspace's image size; at
// level H (images halved H times, as the pyramid's rounds) each pixel takes
// the planes of the full-size pixel under its centre, continued to its own
// ray. Costs are the photometric cost of a pass's start (mean of the 3 best
// views, core::ScorePixel), with the run's defaults for the window.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"
#include "core/patch_match/segment_plane.h"
#include "io/dense_map_io.h"
#include "io/ground_truth.h"
#include "io/workspace.h"
#include "options/tool_command_line.h"
#include "patch_match/problem_level.h"

namespace msp {
namespace {

// A cost difference below this is noise between two planes of one window
// (the segment-plane step's margin for textureless pixels).
constexpr float kAmbiguousCost = 0.1f;
// A pixel is wrong when its depth is off by more than this (the evaluator's
// first threshold).
constexpr float kWrongRelativeDepth = 0.01f;
constexpr float kFarRelativeDepth = 0.05f;  // the evaluator's second threshold

struct Tally {
  long wrong = 0, search = 0, ambiguous = 0, against = 0, right = 0, empty = 0;
  long other_surface = 0;       // wrong pixels on the plane of another large surface
  long far = 0, far_other = 0;  // off by more than kFarRelativeDepth; of them on another surface
  double chosen_cost = 0.0, true_cost = 0.0;

  void Add(const Tally& o) {
    wrong += o.wrong;
    search += o.search;
    ambiguous += o.ambiguous;
    against += o.against;
    right += o.right;
    empty += o.empty;
    other_surface += o.other_surface;
    far += o.far;
    far_other += o.far_other;
    chosen_cost += o.chosen_cost;
    true_cost += o.true_cost;
  }

  void Print(const char* label) const {
    const double n = std::max(1L, wrong);
    const long all = wrong + right + empty;
    std::printf(
        "%-22s %8ld  wrong %5.1f%%  empty %5.1f%% | of wrong: truth cheaper %5.1f%%  tie %5.1f%%  "
        "truth dearer %5.1f%%  (mean cost chosen %.3f, true %.3f); on another surface's plane "
        "%5.1f%%; off by > 5%%: %5.1f%% of wrong, %5.1f%% of them on another surface\n",
        label, all, 100.0 * wrong / std::max(1L, all), 100.0 * empty / std::max(1L, all),
        100.0 * search / n, 100.0 * ambiguous / n, 100.0 * against / n, chosen_cost / n,
        true_cost / n, 100.0 * other_surface / n, 100.0 * far / n,
        100.0 * far_other / std::max(1L, far));
  }
};

float StartCost(const core::PassParams& p, int col, int row, const core::PlaneHypothesis& h) {
  if (!(h.depth > 0.0f)) return core::kMaxCost;
  core::RefWindow w;
  core::PrepareWindow(p, col, row, &w);
  float costs[core::kMaxSourceViews];
  core::ViewCosts(p, w, h, nullptr, costs);
  return core::TopViewsCost(costs, p.num_src);
}

// The plane of full-size pixel (gc, gr) of a depth/normal pair, continued to
// pixel (col, row) of `camera`; depth 0 when there is none.
core::PlaneHypothesis PlaneAt(const DenseMap& depth, const DenseMap& normal,
                              const core::Camera& full, const core::Camera& camera, int gc, int gr,
                              int col, int row) {
  const float d = depth.At(gr, gc);
  if (!(d > 0.0f)) return core::PlaneHypothesis{0.0f, core::Vec3{0, 0, -1}};
  const core::Vec3 n{normal.At(gr, gc, 0), normal.At(gr, gc, 1), normal.At(gr, gc, 2)};
  const core::Vec3 X = core::BackProject(full, static_cast<float>(gc), static_cast<float>(gr), d);
  core::PlaneHypothesis h = core::HypothesisOnPlane(camera, col, row, n, X);
  h.normal = n;
  return h;
}

// The large planar surfaces of an image's ground truth: planes n.X + d = 0
// (camera frame) holding at least kMinSurfaceShare of its pixels.
struct Surface {
  core::Vec3 n;
  float d;
};
constexpr double kMinSurfaceShare = 0.005;
// Plane parameters are grouped at these steps (unit normal, metres).
constexpr float kNormalStep = 0.05f;
constexpr float kOffsetStep = 0.02f;
// A point lies on a surface within this share of its depth, with a normal
// within this angle.
constexpr float kOnSurfaceDepth = 0.01f;
constexpr float kOnSurfaceCosine = -2.0f;  // any normal (textureless normals are noise)
// Two surfaces are one when their normals and offsets are this close.
constexpr float kSameSurfaceCosine = 0.966f;  // 15 degrees
constexpr float kSameSurfaceOffset = 0.05f;   // metres

std::vector<Surface> LargeSurfaces(const DenseMap& depth, const DenseMap& normal,
                                   const core::Camera& camera) {
  std::map<std::array<int, 4>, std::pair<long, Surface>> groups;
  for (int row = 0; row < depth.height; ++row) {
    for (int col = 0; col < depth.width; ++col) {
      const float z = depth.At(row, col);
      if (!(z > 0.0f)) continue;
      const core::Vec3 n{normal.At(row, col, 0), normal.At(row, col, 1), normal.At(row, col, 2)};
      const core::Vec3 X =
          core::BackProject(camera, static_cast<float>(col), static_cast<float>(row), z);
      const float d = -core::Dot(n, X);
      const std::array<int, 4> key{static_cast<int>(std::lround(n.x / kNormalStep)),
                                   static_cast<int>(std::lround(n.y / kNormalStep)),
                                   static_cast<int>(std::lround(n.z / kNormalStep)),
                                   static_cast<int>(std::lround(d / kOffsetStep))};
      auto& g = groups[key];
      if (g.first++ == 0) g.second = Surface{n, d};
    }
  }
  std::vector<Surface> surfaces;
  const double min_pixels = kMinSurfaceShare * depth.width * depth.height;
  for (const auto& g : groups) {
    if (g.second.first >= min_pixels) surfaces.push_back(g.second.second);
  }
  return surfaces;
}

// Whether X (normal n) lies on a surface other than `own`, the pixel's true plane.
bool OnOtherSurface(const std::vector<Surface>& surfaces, const Surface& own, const core::Vec3& X,
                    const core::Vec3& n) {
  for (const Surface& s : surfaces) {
    const bool is_own =
        core::Dot(s.n, own.n) > kSameSurfaceCosine && std::fabs(s.d - own.d) < kSameSurfaceOffset;
    if (!is_own && std::fabs(core::Dot(s.n, X) + s.d) < kOnSurfaceDepth * X.z &&
        core::Dot(s.n, n) > kOnSurfaceCosine) {
      return true;
    }
  }
  return false;
}

void Run(const std::string& workspace_path, int halvings, const std::string& input_type) {
  StereoCommandOptions options;
  options.workspace_path = workspace_path;
  options.msp.segmentation_prior = false;  // no mask layers needed
  const Workspace ws = LoadWorkspace(options);
  const GroundTruthInfo gt = ReadGroundTruthInfo(GroundTruthDir(workspace_path, ""));
  Tally textureless_all, textured_all;
  std::printf(
      "level: images halved %d times; wrong = depth off by > %.0f%%, tie = costs within %.2f\n",
      halvings, 100.0 * kWrongRelativeDepth, kAmbiguousCost);
  for (const Problem& problem : ws.problems) {
    const View& ref = ws.views[problem.ref];
    const DenseMap depth = ReadDenseMap(DepthMapPath(workspace_path, ref.name, input_type));
    const DenseMap normal = ReadDenseMap(NormalMapPath(workspace_path, ref.name, input_type));
    const DenseMap gt_depth = ReadDenseMap(gt.DepthMapPath(ref.name));
    const DenseMap gt_normal = ReadDenseMap(gt.NormalMapPath(ref.name));
    const cv::Mat flat = cv::imread(gt.TexturelessPath(ref.name), cv::IMREAD_GRAYSCALE);
    if (depth.width != gt_depth.width || flat.cols != gt_depth.width) {
      throw std::runtime_error(ref.name + ": maps and ground truth differ in size");
    }
    const std::vector<Surface> surfaces = LargeSurfaces(gt_depth, gt_normal, ref.camera);
    std::vector<int> ids = problem.srcs;
    ids.push_back(problem.ref);
    const Level level = BuildLevel(ws.views, ids, -1, halvings);
    core::PassParams p{};
    p.ref_camera = level.cameras.at(problem.ref);
    const DenseMap& img = level.gray.at(problem.ref);
    p.ref_image = core::ImageView{img.data.data(), img.width, img.height, img.width};
    p.num_src = std::min<int>(static_cast<int>(problem.srcs.size()), core::kMaxSourceViews);
    for (int j = 0; j < p.num_src; ++j) {
      core::SourceView& s = p.src[j];
      s.camera = level.cameras.at(problem.srcs[j]);
      s.rel = core::ComputeRelativePose(p.ref_camera, s.camera);
      const DenseMap& src = level.gray.at(problem.srcs[j]);
      s.image = core::ImageView{src.data.data(), src.width, src.height, src.width};
    }
    p.ncc.window_radius = options.patch_match.window_radius;
    p.ncc.window_step = options.msp.window_step;
    p.depth_min = problem.depth_min;
    p.depth_max = problem.depth_max;
    Tally textureless, textured;
    const int scale = 1 << halvings;
    for (int row = 0; row < p.ref_camera.height; ++row) {
      for (int col = 0; col < p.ref_camera.width; ++col) {
        const int gc = std::min(col * scale + scale / 2, depth.width - 1);
        const int gr = std::min(row * scale + scale / 2, depth.height - 1);
        if (!(gt_depth.At(gr, gc) > 0.0f)) continue;
        Tally& t = flat.at<uint8_t>(gr, gc) != 0 ? textureless : textured;
        const core::PlaneHypothesis truth =
            PlaneAt(gt_depth, gt_normal, ref.camera, p.ref_camera, gc, gr, col, row);
        const core::PlaneHypothesis chosen =
            PlaneAt(depth, normal, ref.camera, p.ref_camera, gc, gr, col, row);
        if (!(chosen.depth > 0.0f)) {
          ++t.empty;
          continue;
        }
        if (std::fabs(chosen.depth - truth.depth) <= kWrongRelativeDepth * truth.depth) {
          ++t.right;
          continue;
        }
        ++t.wrong;
        const core::Vec3 X = core::BackProject(ref.camera, static_cast<float>(gc),
                                               static_cast<float>(gr), depth.At(gr, gc));
        const core::Vec3 n{normal.At(gr, gc, 0), normal.At(gr, gc, 1), normal.At(gr, gc, 2)};
        const core::Vec3 true_n{gt_normal.At(gr, gc, 0), gt_normal.At(gr, gc, 1),
                                gt_normal.At(gr, gc, 2)};
        const core::Vec3 true_X = core::BackProject(ref.camera, static_cast<float>(gc),
                                                    static_cast<float>(gr), gt_depth.At(gr, gc));
        const bool other =
            OnOtherSurface(surfaces, Surface{true_n, -core::Dot(true_n, true_X)}, X, n);
        t.other_surface += other ? 1 : 0;
        if (std::fabs(chosen.depth - truth.depth) > kFarRelativeDepth * truth.depth) {
          ++t.far;
          t.far_other += other ? 1 : 0;
        }
        const float c_chosen = StartCost(p, col, row, chosen);
        const float c_true = StartCost(p, col, row, truth);
        t.chosen_cost += c_chosen;
        t.true_cost += c_true;
        if (c_true < c_chosen - kAmbiguousCost) {
          ++t.search;
        } else if (c_true > c_chosen + kAmbiguousCost) {
          ++t.against;
        } else {
          ++t.ambiguous;
        }
      }
    }
    textureless.Print((ref.name + " textureless").c_str());
    textureless_all.Add(textureless);
    textured_all.Add(textured);
  }
  textureless_all.Print("all textureless");
  textured_all.Print("all textured");
}

}  // namespace
}  // namespace msp

int main(int argc, char** argv) {
  std::string workspace, input_type = "geometric";
  int halvings = 0;
  msp::ToolCommandLine command_line(
      "Usage: msp_plane_costs --workspace <ws> [--halvings H]",
      "On the pixels whose depth is wrong, compares the matching cost of the\n"
      "run's plane with the ground truth's, at pyramid level H.");
  command_line.AddRequired("workspace", &workspace, "Workspace with maps and ground_truth/.");
  command_line.Add("halvings", &halvings, "Pyramid level: images halved this many times.");
  command_line.AddChoice("input_type", &input_type, {"geometric", "photometric"},
                         "Which maps to read.");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    msp::Run(workspace, halvings, input_type);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
  return 0;
}
