// The two graph segmenters of --MspStereo.segmenter (OpenCV contrib's and
// this project's) on a workspace of the bundled scene, at the sizes of the
// rounds a run makes: time per segmentation and where the segment edges lie
// against the ground truth. For the colour layers of the embedded segmenter
// (SegmentationScale, the same sigma / k / min_size for both) and for the
// geometry layers of the ground-truth depth and normal maps (what the
// geometry layers would see with perfect maps).
//
//   msp_bench_segmenters --workspace WS [--max_image_size 320] [--repeats 5]
//
// A segment edge pixel (a pixel whose 4-neighbour has another label) is "on a
// depth edge" when it lies within one pixel of a ground-truth depth edge: a
// 3 % depth jump between neighbours at the ground truth's resolution, marked
// on every map pixel whose footprint holds one. "On a surface edge" adds the
// creases (normals more than 20 degrees apart). Recall is the share of the
// depth edge pixels within one pixel of a segment edge.
#include <time.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "core/prior/prior_limits.h"
#include "io/dense_map_io.h"
#include "io/ground_truth.h"
#include "io/workspace.h"
#include "options/tool_command_line.h"
#include "patch_match/image_pyramid.h"
#include "prior/geometry_layers.h"
#include "prior/multiscale_segmentation.h"
#include "prior/segmentation_prior.h"

namespace msp {
namespace {

constexpr float kDepthEdgeJump = 0.03f;   // as bench/edge_accuracy.py
constexpr float kCreaseCosine = 0.9397f;  // cos 20 degrees
constexpr int kNumColourLevels = 3;       // --MspStereo.advanced_num_mask_levels default
constexpr Segmenter kSegmenters[] = {Segmenter::kOpenCv, Segmenter::kEmbedded};

double ThreadCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// Depth edges (and, with creases, normal creases) of the ground truth, marked
// on the w x h map pixels whose footprint holds one.
std::vector<uint8_t> TrueEdges(const DenseMap& depth, const DenseMap& normal, int w, int h,
                               bool creases) {
  std::vector<uint8_t> edges(static_cast<size_t>(w) * h, 0);
  const int W = depth.width, H = depth.height;
  auto mark = [&](int row, int col) {
    edges[static_cast<size_t>(std::min(row * h / H, h - 1)) * w + std::min(col * w / W, w - 1)] = 1;
  };
  for (int row = 0; row < H; ++row) {
    for (int col = 0; col < W; ++col) {
      for (int d = 0; d < 2; ++d) {
        const int r2 = row + d, c2 = col + 1 - d;
        if (r2 >= H || c2 >= W) continue;
        const float a = depth.At(row, col), b = depth.At(r2, c2);
        if (!(a > 0.0f && b > 0.0f)) continue;
        bool edge = std::fabs(a - b) > kDepthEdgeJump * std::min(a, b);
        if (creases) {
          float dot = 0.0f;
          for (int c = 0; c < 3; ++c) dot += normal.At(row, col, c) * normal.At(r2, c2, c);
          edge = edge || dot < kCreaseCosine;
        }
        if (edge) {
          mark(row, col);
          mark(r2, c2);
        }
      }
    }
  }
  return edges;
}

bool Near(const std::vector<uint8_t>& map, int w, int h, int row, int col) {
  for (int r = std::max(0, row - 1); r <= std::min(h - 1, row + 1); ++r) {
    for (int c = std::max(0, col - 1); c <= std::min(w - 1, col + 1); ++c) {
      if (map[static_cast<size_t>(r) * w + c]) return true;
    }
  }
  return false;
}

struct EdgeFigures {
  double edge_pixels = 0, on_depth = 0, on_surface = 0, depth_pixels = 0, recalled = 0;
  double regions = 0, seconds = 0, count = 0;
  void Print(const char* what) const {
    std::printf(
        "  %-26s %7.2f ms %6.0f regions  edges %5.1f%% of px  on depth edges %5.1f%%  "
        "on depth edges or creases %5.1f%%  recall %5.1f%%\n",
        what, 1e3 * seconds / count, regions / count, 100.0 * edge_pixels / depth_pixels_total,
        100.0 * on_depth / edge_pixels, 100.0 * on_surface / edge_pixels,
        100.0 * recalled / depth_pixels);
  }
  double depth_pixels_total = 0;  // all map pixels
};

void Score(const std::vector<int32_t>& labels, int w, int h, const std::vector<uint8_t>& depth,
           const std::vector<uint8_t>& surface, EdgeFigures* f) {
  const std::vector<uint8_t> b = ComputeBoundaryMap(labels, w, h);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const size_t i = static_cast<size_t>(row) * w + col;
      if (b[i]) {
        f->edge_pixels += 1;
        f->on_depth += Near(depth, w, h, row, col);
        f->on_surface += Near(surface, w, h, row, col);
      }
      if (depth[i]) {
        f->depth_pixels += 1;
        f->recalled += Near(b, w, h, row, col);
      }
    }
  }
  int32_t max_id = 0;
  for (int32_t id : labels) max_id = std::max(max_id, id);
  f->regions += max_id;
  f->depth_pixels_total += static_cast<double>(w) * h;
}

// The ground truth resampled to the map by nearest neighbour.
DenseMap Nearest(const DenseMap& map, int w, int h) {
  DenseMap out(w, h, map.channels);
  for (int c = 0; c < map.channels; ++c) {
    for (int row = 0; row < h; ++row) {
      for (int col = 0; col < w; ++col) {
        out.At(row, col, c) = map.At(NearestGroundTruthIndex(row, h, map.height),
                                     NearestGroundTruthIndex(col, w, map.width), c);
      }
    }
  }
  return out;
}

struct BenchOptions {
  std::string workspace;
  int max_image_size = 320;
  int repeats = 5;
};

void Run(const BenchOptions& options) {
  StereoCommandOptions stereo;
  stereo.workspace_path = options.workspace;
  stereo.patch_match.max_image_size = options.max_image_size;
  const Workspace ws = LoadWorkspace(stereo);
  const GroundTruthInfo gt = ReadGroundTruthInfo(GroundTruthDir(options.workspace, ""));
  std::vector<DenseMap> colors;
  std::vector<std::string> names;
  for (const Problem& problem : ws.problems) {
    colors.push_back(ws.views[problem.ref].color);
    names.push_back(ws.views[problem.ref].name);
  }
  for (int halvings = 0; colors[0].width >= 64; ++halvings) {
    const int w = colors[0].width, h = colors[0].height;
    std::printf("%dx%d (%d halvings), %zu images, %d repeats, one thread\n", w, h, halvings,
                colors.size(), options.repeats);
    for (Segmenter s : kSegmenters) {
      EdgeFigures colour[kNumColourLevels], all_colour, geometry[core::kNumGeometryLayers];
      for (size_t v = 0; v < colors.size(); ++v) {
        const DenseMap gt_depth = ReadDenseMap(gt.DepthMapPath(names[v]));
        const DenseMap gt_normal = ReadDenseMap(gt.NormalMapPath(names[v]));
        const std::vector<uint8_t> depth_edges = TrueEdges(gt_depth, gt_normal, w, h, false);
        const std::vector<uint8_t> surface_edges = TrueEdges(gt_depth, gt_normal, w, h, true);
        for (int level = 0; level < kNumColourLevels; ++level) {
          const GraphSegmentationScale scale = SegmentationScale(level, kNumColourLevels, w, h);
          std::vector<int32_t> labels;
          const double t0 = ThreadCpuSeconds();
          for (int r = 0; r < options.repeats; ++r) labels = SegmentGraph(colors[v], scale, s);
          colour[level].seconds += (ThreadCpuSeconds() - t0) / options.repeats;
          colour[level].count += 1;
          Score(labels, w, h, depth_edges, surface_edges, &colour[level]);
        }
        const double t0 = ThreadCpuSeconds();
        for (int r = 0; r < options.repeats; ++r) SegmentMultiscale(colors[v], kNumColourLevels, s);
        all_colour.seconds += (ThreadCpuSeconds() - t0) / options.repeats;
        all_colour.count += 1;
        const DenseMap depth = Nearest(gt_depth, w, h), normal = Nearest(gt_normal, w, h);
        LabelLayers layers;
        const double t1 = ThreadCpuSeconds();
        for (int r = 0; r < options.repeats; ++r) layers = SegmentGeometry(depth, normal, s, 1);
        const double geometry_seconds = (ThreadCpuSeconds() - t1) / options.repeats;
        for (int level = 0; level < core::kNumGeometryLayers; ++level) {
          geometry[level].seconds += geometry_seconds / core::kNumGeometryLayers;
          geometry[level].count += 1;
          Score(layers.levels[level], w, h, depth_edges, surface_edges, &geometry[level]);
        }
      }
      std::printf(" %s:\n", SegmenterName(s));
      for (int level = 0; level < kNumColourLevels; ++level) {
        const std::string what = "colour level " + std::to_string(level);
        colour[level].Print(what.c_str());
      }
      std::printf("  %-26s %7.2f ms (the %d colour levels in one call)\n", "colour, all levels",
                  1e3 * all_colour.seconds / all_colour.count, kNumColourLevels);
      for (int level = 0; level < core::kNumGeometryLayers; ++level) {
        const std::string what = "geometry (GT maps) " + std::to_string(level);
        geometry[level].Print(what.c_str());
      }
    }
    for (DenseMap& c : colors) c = DownsampleHalf(c);
  }
}

}  // namespace
}  // namespace msp

int main(int argc, char** argv) {
  msp::BenchOptions options;
  msp::ToolCommandLine command_line(
      "Usage: msp_bench_segmenters --workspace <ws> [--max_image_size 320] [--repeats 5]",
      "Time per segmentation and share of segment edges on ground-truth depth edges of\n"
      "the two graph segmenters (--MspStereo.segmenter), on the reference images of a\n"
      "bundled-scene workspace at every round size down to 64 px wide.");
  command_line.AddRequired("workspace", &options.workspace,
                           "Workspace with images/, sparse/, stereo/ and ground_truth/.");
  command_line.Add("max_image_size", &options.max_image_size,
                   "Images downsized to this larger side first (as msp_stereo).");
  command_line.Add("repeats", &options.repeats, "Segmentations per timing (>= 1).");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    if (options.repeats < 1) throw std::invalid_argument("--repeats must be >= 1");
    msp::Run(options);
  } catch (const std::exception& e) {
    std::cerr << "ERROR: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
