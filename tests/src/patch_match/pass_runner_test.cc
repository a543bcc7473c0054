#include "patch_match/pass_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "backend/cpu/cpu_entry.h"
#include "base/label_layers.h"
#include "tests/support/memory_exchange.h"
#include "tests/support/synthetic_views.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

// The default options with deformable patches on (off by default), whose
// schedule and outputs these tests pin down.
MspStereoOptions WithDeformable() {
  MspStereoOptions msp;
  msp.deformable = true;
  return msp;
}

// Keeps every written map in memory.
class MemorySink : public MapSink {
 public:
  bool HasFinalOutput(int view) const override { return done.count(view) > 0; }
  void Write(int view, const std::string& type, const DenseMap& depth,
             const DenseMap& normal) override {
    maps[{view, type}] = {depth, normal};
  }
  void WritePriorPreview(int view, const DenseMap& color, const std::vector<uint8_t>& aggregated,
                         const std::vector<uint8_t>& refined) override {
    previews[view] = {aggregated, refined};
    preview_sizes[view] = {color.width, color.height};
  }
  void WriteMapPreviews(int view, const DenseMap& depth, const DenseMap& normal) override {
    EXPECT_FALSE(maps.count({view, "geometric"})) << "pictures come before the final maps";
    map_previews[view] = {depth, normal};
  }
  std::map<std::pair<int, std::string>, std::pair<DenseMap, DenseMap>> maps;
  std::map<int, std::pair<std::vector<uint8_t>, std::vector<uint8_t>>> previews;
  std::map<int, std::pair<int, int>> preview_sizes;
  std::map<int, std::pair<DenseMap, DenseMap>> map_previews;
  std::map<int, bool> done;
};

constexpr float kPlaneDepth = 2.0f;

// Every map of `a` is in `b`, with the same depths and normals bit for bit.
void ExpectSameMaps(const MemorySink& a, const MemorySink& b) {
  ASSERT_EQ(a.maps.size(), b.maps.size());
  for (const auto& entry : a.maps) {
    ASSERT_TRUE(b.maps.count(entry.first)) << entry.first.first << " " << entry.first.second;
    const auto& other = b.maps.at(entry.first);
    EXPECT_EQ(entry.second.first.data, other.first.data) << entry.first.second;
    EXPECT_EQ(entry.second.second.data, other.second.data) << entry.first.second;
  }
}

std::vector<Problem> AllProblems(int num_views) {
  std::vector<Problem> problems;
  for (int v = 0; v < num_views; ++v) {
    Problem p;
    p.ref = v;
    for (int s = 0; s < num_views; ++s) {
      if (s != v) p.srcs.push_back(s);
    }
    p.depth_min = 1.0f;
    p.depth_max = 4.0f;
    problems.push_back(p);
  }
  return problems;
}

TEST(PatchMatchCpu, RecoversFrontoParallelPlane) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(96, 72, 4, kPlaneDepth, 0.25f);
  const std::vector<Problem> problems = AllProblems(4);
  PatchMatchStereoOptions pm;
  MspStereoOptions msp = WithDeformable();
  msp.num_threads = 2;
  MemorySink sink;
  const test::TempDir scratch;
  RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), sink);
  const auto it = sink.maps.find({0, std::string("geometric")});
  ASSERT_NE(it, sink.maps.end());
  const DenseMap& depth = it->second.first;
  const DenseMap& normal = it->second.second;
  int valid = 0, accurate = 0, total = 0;
  // Away from the border, where every source sees the plane.
  for (int r = 12; r < depth.height - 12; ++r) {
    for (int c = 12; c < depth.width - 12; ++c) {
      ++total;
      const float d = depth.At(r, c);
      if (d <= 0.0f) continue;
      ++valid;
      if (std::fabs(d - kPlaneDepth) < /*max_rel_depth_error=*/0.005f * kPlaneDepth) ++accurate;
      const float nz = normal.At(r, c, 2);
      EXPECT_NEAR(std::sqrt(normal.At(r, c, 0) * normal.At(r, c, 0) +
                            normal.At(r, c, 1) * normal.At(r, c, 1) + nz * nz),
                  1.0f, 1e-4f);
      EXPECT_LT(nz, 0.0f);  // facing the camera
    }
  }
  EXPECT_GT(valid, 0.9 * total);
  EXPECT_GT(accurate, 0.95 * valid);
  EXPECT_TRUE(sink.maps.count({0, std::string("photometric")}));
}

// With the segmentation prior on (the default) and off: the same seed gives
// the same maps, and the prior the same edges, on 1 and 2 threads. The
// embedded segmenter cuts this plane's noise texture into regions (OpenCV's
// leaves it whole), so the prior has edges that confine.
TEST(PatchMatchCpu, DeterministicAcrossThreadCountsWithAndWithoutPrior) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(48, 40, 3, kPlaneDepth, 0.25f);
  const std::vector<Problem> problems = AllProblems(3);
  PatchMatchStereoOptions pm;
  const test::TempDir scratch;
  for (bool prior : {true, false}) {
    MspStereoOptions msp = WithDeformable();
    msp.seed = 3;
    msp.segmentation_prior = prior;
    msp.segmenter = "embedded";
    msp.write_previews = true;  // the edges that confined the last pass, to compare
    MemorySink one, two;
    msp.num_threads = 1;
    RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), one);
    msp.num_threads = 2;
    RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), two);
    SCOPED_TRACE(prior ? "with the prior" : "without the prior");
    ExpectSameMaps(one, two);
    EXPECT_EQ(one.previews, two.previews);
    if (!prior) {
      EXPECT_TRUE(one.previews.empty());
      continue;
    }
    ASSERT_EQ(one.previews.size(), 3u);
    long long edge_pixels = 0;
    for (const auto& preview : one.previews) {
      for (uint8_t e : preview.second.second) edge_pixels += e;
    }
    EXPECT_GT(edge_pixels, 0) << "the prior must have made edges to confine with";
  }
}

// Both segmenters, with and without the geometry layers: the same seed gives
// the same maps and prior edges on 1 and 2 threads.
TEST(PatchMatchCpu, DeterministicWithBothSegmentersAndGeometryLayers) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(48, 40, 3, kPlaneDepth, 0.25f);
  const std::vector<Problem> problems = AllProblems(3);
  PatchMatchStereoOptions pm;
  const test::TempDir scratch;
  for (const char* segmenter : {"opencv", "embedded"}) {
    for (bool geometry : {true, false}) {
      SCOPED_TRACE(std::string(segmenter) + (geometry ? " with" : " without") + " geometry layers");
      MspStereoOptions msp = WithDeformable();
      msp.seed = 5;
      msp.segmenter = segmenter;
      msp.geometry_layers = geometry;
      msp.write_previews = true;
      MemorySink one, two;
      msp.num_threads = 1;
      RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), one);
      msp.num_threads = 2;
      RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), two);
      ExpectSameMaps(one, two);
      EXPECT_EQ(one.previews, two.previews);
      EXPECT_EQ(one.previews.size(), 3u);
    }
  }
}

// A reference view with user mask layers uses them, not the embedded
// segmenter: its one layer (two regions split at column kSplit) is the only
// layer, so every region is kept and B' is exactly the split, 2 px wide.
// Views without layers get the segmenter's edges. Previews show both.
TEST(PatchMatchCpu, UserMaskLayersAreUsedOverTheEmbeddedSegmenter) {
  constexpr int kWidth = 48, kHeight = 40, kSplit = 20;
  std::vector<View> views = test::RenderFrontoParallelPlane(kWidth, kHeight, 3, kPlaneDepth, 0.25f);
  LabelLayers layers;
  layers.width = kWidth;
  layers.height = kHeight;
  layers.levels.assign(1, std::vector<int32_t>(kWidth * kHeight));
  for (int i = 0; i < kWidth * kHeight; ++i) layers.levels[0][i] = i % kWidth < kSplit ? 1 : 2;
  views[0].mask_layers.source = LabelSource::kMaskFiles;
  views[0].mask_layers.layers = layers;
  PatchMatchStereoOptions pm;
  MspStereoOptions msp = WithDeformable();
  msp.write_previews = true;
  msp.edge_refinement = false;  // B' itself confines
  MemorySink sink;
  const test::TempDir scratch;
  RunPatchMatchCpu(views, AllProblems(3), pm, msp, scratch.path(), sink);
  ASSERT_EQ(sink.previews.size(), 3u);
  const std::vector<uint8_t>& aggregated = sink.previews.at(0).first;
  ASSERT_EQ(aggregated.size(), static_cast<size_t>(kWidth * kHeight));
  EXPECT_TRUE(sink.previews.at(0).second.empty() ||
              std::count(sink.previews.at(0).second.begin(), sink.previews.at(0).second.end(),
                         1) == 0);  // no refined edges without the CRF
  EXPECT_EQ(sink.preview_sizes.at(0), std::make_pair(kWidth, kHeight));
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const int col = i % kWidth;
    EXPECT_EQ(aggregated[i], (col == kSplit - 1 || col == kSplit) ? 1 : 0) << i;
  }
  // The embedded segmenter on the others' colour images finds other edges.
  for (int v = 1; v < 3; ++v) {
    const std::vector<uint8_t>& edges = sink.previews.at(v).first;
    ASSERT_EQ(edges.size(), static_cast<size_t>(kWidth * kHeight));
    EXPECT_NE(edges, aggregated);
  }
}

constexpr float kStripDepth = 1.5f, kWallDepth = 3.0f, kStripHalfWidth = 0.2f;

// True when pixel (col, row) of `cam` sees the strip (the world's x within
// kStripHalfWidth at z = kStripDepth), which stands before the wall.
bool SeesStrip(const core::Camera& cam, int col, int row) {
  return std::fabs(test::PointOnPlaneZ(cam, col, row, kStripDepth).x) <= kStripHalfWidth;
}

// Views of a strongly textured vertical strip (a box, depth 1.5) before a
// wall of weak texture (depth 3), sources to the left and right; each view
// with the objects as its one mask layer (strip 1, wall 2) when `masks`.
std::vector<View> RenderStripBeforeWall(int width, int height, bool masks) {
  std::vector<View> views;
  for (const float x : {0.0f, -0.25f, 0.25f, -0.5f}) {
    View view;
    view.name = "view_" + std::to_string(views.size()) + ".png";
    view.camera = test::CentredCamera(width, height, core::Vec3{x, 0.0f, 0.0f});
    view.gray = DenseMap(width, height, 1);
    view.color = DenseMap(width, height, 3);
    LabelLayers objects;
    objects.width = width;
    objects.height = height;
    objects.levels.assign(1, std::vector<int32_t>(width * height));
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) {
        const bool strip = SeesStrip(view.camera, c, r);
        const core::Vec3 X =
            test::PointOnPlaneZ(view.camera, c, r, strip ? kStripDepth : kWallDepth);
        const float texture = test::MultiScaleTexture(X.x, X.y);
        const float g = strip ? texture : 0.5f + 0.3f * (texture - 0.5f);
        view.gray.At(r, c) = g;
        for (int k = 0; k < 3; ++k) view.color.At(r, c, k) = g;
        objects.levels[0][r * width + c] = strip ? 1 : 2;
      }
    }
    if (masks) {
      view.mask_layers.source = LabelSource::kMaskFiles;
      view.mask_layers.layers = objects;
    }
    views.push_back(std::move(view));
  }
  return views;
}

// The reference's wall pixels within 4 px of the strip's outline, and how
// many of them hold the wall's depth or the strip's (within 2 %).
struct NearStrip {
  int pixels = 0, wall = 0, strip = 0;
};

NearStrip WallNearTheStrip(bool masks, bool region_windows) {
  constexpr int kWidth = 96, kHeight = 72;
  const std::vector<View> views = RenderStripBeforeWall(kWidth, kHeight, masks);
  PatchMatchStereoOptions pm;
  MspStereoOptions msp;
  msp.region_windows = region_windows;
  MemorySink sink;
  const test::TempDir scratch;
  RunPatchMatchCpu(views, AllProblems(4), pm, msp, scratch.path(), sink);
  const DenseMap& depth = sink.maps.at({0, std::string("geometric")}).first;
  const core::Camera& cam = views[0].camera;
  NearStrip near;
  for (int r = 8; r < kHeight - 8; ++r) {
    for (int c = 8; c < kWidth - 8; ++c) {
      if (SeesStrip(cam, c, r)) continue;
      bool by_strip = false;
      for (int dc = -4; dc <= 4; ++dc) by_strip = by_strip || SeesStrip(cam, c + dc, r);
      if (!by_strip) continue;
      ++near.pixels;
      near.wall += std::fabs(depth.At(r, c) - kWallDepth) < 0.02f * kWallDepth;
      near.strip += std::fabs(depth.At(r, c) - kStripDepth) < 0.02f * kStripDepth;
    }
  }
  return near;
}

// Near the strip the wall's whole windows are mostly the strip's texture
// and match at its depth: the strip grows over the wall. With the objects as
// mask layers the wall's windows keep only the wall: none of its pixels
// takes the strip's depth, and those two sources see take the wall's (the
// others, hidden by the strip from the sources on its left, are left
// empty). It is the windows that do it: with the switch off the masks still
// bound the planes, and the strip grows as without masks.
TEST(PatchMatchCpu, WindowsBoundedByTheObjectsKeepTheWallOffTheStripsDepth) {
  for (const bool masks : {false, true}) {
    const NearStrip whole = WallNearTheStrip(masks, /*region_windows=*/false);
    ASSERT_GT(whole.pixels, 400);
    EXPECT_GT(whole.strip, 0.9 * whole.pixels) << masks;
    EXPECT_EQ(whole.wall, 0) << masks;
  }
  const NearStrip bounded = WallNearTheStrip(/*masks=*/true, /*region_windows=*/true);
  EXPECT_LT(bounded.strip, 0.02 * bounded.pixels);
  EXPECT_GT(bounded.wall, 0.25 * bounded.pixels);
}

// A cache budget smaller than one image's state spills every other state to
// the scratch folder between passes; the maps must not change.
TEST(PatchMatchCpu, SpillingStateGivesIdenticalMaps) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(48, 36, 3, kPlaneDepth, 0.25f);
  const std::vector<Problem> problems = AllProblems(3);
  PatchMatchStereoOptions pm;
  MspStereoOptions msp = WithDeformable();
  MemorySink in_memory, spilled;
  const test::TempDir scratch;
  RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), in_memory);
  pm.cache_size = 1e-6;  // ~1 kB
  RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), spilled);
  ExpectSameMaps(in_memory, spilled);
}

// The geometric term in depth takes --MspStereo.geom_consistency_depth_weight;
// COLMAP's geom_consistency_regularizer weighs only the term in pixels.
TEST(PatchMatchCpu, GeometricTermInDepthTakesItsOwnWeight) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(48, 36, 3, kPlaneDepth, 0.25f);
  const std::vector<Problem> problems = AllProblems(3);
  const test::TempDir scratch;
  auto run = [&](double regularizer, double depth_weight, double depth_error) {
    PatchMatchStereoOptions pm;
    pm.geom_consistency_regularizer = regularizer;
    MspStereoOptions msp;
    msp.geom_consistency_depth_weight = depth_weight;
    msp.geom_consistency_depth_error = depth_error;
    MemorySink sink;
    RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), sink);
    return sink;
  };
  // The geometric maps of the last pass, whose sweeps the term weighs.
  auto depths = [](const MemorySink& sink) { return sink.maps.at({0, "geometric"}).first.data; };
  const MemorySink in_depth = run(0.3, 0.2, 0.01);
  ExpectSameMaps(in_depth, run(2.0, 0.2, 0.01));
  EXPECT_NE(depths(in_depth), depths(run(0.3, 2.0, 0.01)));
  const MemorySink in_pixels = run(0.3, 0.2, 0.0);
  ExpectSameMaps(in_pixels, run(0.3, 2.0, 0.0));
  EXPECT_NE(depths(in_pixels), depths(run(2.0, 0.2, 0.0)));
}

// Views whose images are not in memory are read by their load_images each
// time a problem needs them (a workspace beyond the cache's image share);
// the maps must not change, with or without spilled state.
TEST(PatchMatchCpu, ImagesReadOnDemandGiveIdenticalMaps) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(48, 36, 4, kPlaneDepth, 0.25f);
  const std::vector<Problem> problems = AllProblems(4);
  std::vector<View> on_demand = views;
  int num_loads = 0;
  for (size_t v = 0; v < on_demand.size(); ++v) {
    on_demand[v].gray = DenseMap();
    on_demand[v].color = DenseMap();
    on_demand[v].load_images = [&views, &num_loads, v](DenseMap* gray, DenseMap* color) {
      ++num_loads;
      if (gray != nullptr) *gray = views[v].gray;
      if (color != nullptr) *color = views[v].color;
    };
  }
  PatchMatchStereoOptions pm;
  MspStereoOptions msp = WithDeformable();
  const test::TempDir scratch;
  MemorySink in_memory;
  RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), in_memory);
  for (double cache_size : {32.0, 1e-6}) {
    pm.cache_size = cache_size;
    MemorySink read_on_demand;
    num_loads = 0;
    RunPatchMatchCpu(on_demand, problems, pm, msp, scratch.path(), read_on_demand);
    ExpectSameMaps(in_memory, read_on_demand);
    // Every image-pass reads its problem's four views, and the first pass
    // of each later round its reference's again for the upsampling.
    EXPECT_GE(num_loads, 4 * 4 * 4);
  }
}

// With write_previews the pictures show exactly the final maps, with or
// without deformable patches (and so the prior); a view whose outputs exist
// gets none, and without the option there are none.
TEST(PatchMatchCpu, MapPreviewsShowTheFinalMapsWithOrWithoutThePrior) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(40, 32, 3, kPlaneDepth, 0.25f);
  PatchMatchStereoOptions pm;
  const test::TempDir scratch;
  for (bool deformable : {true, false}) {
    SCOPED_TRACE(deformable ? "deformable" : "conventional");
    MspStereoOptions msp = WithDeformable();
    msp.deformable = deformable;
    msp.write_previews = true;
    MemorySink sink;
    sink.done[2] = true;
    RunPatchMatchCpu(views, AllProblems(3), pm, msp, scratch.path(), sink);
    ASSERT_EQ(sink.map_previews.size(), 2u);
    for (int v = 0; v < 2; ++v) {
      const auto& written = sink.maps.at({v, "geometric"});
      EXPECT_EQ(sink.map_previews.at(v).first.data, written.first.data);
      EXPECT_EQ(sink.map_previews.at(v).second.data, written.second.data);
    }
    EXPECT_EQ(sink.previews.size(), deformable ? 2u : 0u);  // the prior's own preview
  }
  MspStereoOptions msp = WithDeformable();
  msp.deformable = false;
  MemorySink sink;
  RunPatchMatchCpu(views, AllProblems(3), pm, msp, scratch.path(), sink);
  EXPECT_EQ(sink.maps.size(), 6u);
  EXPECT_TRUE(sink.map_previews.empty());
}

// Two shards of one run, each in a thread with its own sink, meet at the
// pass barriers: each writes only its images' maps, and those are the maps
// of the run in one process, bit for bit.
TEST(PatchMatchCpu, ShardsTogetherGiveTheOneProcessMaps) {
  MspStereoOptions msp = WithDeformable();
  msp.seed = 5;
  msp.num_threads = 1;
  const PatchMatchStereoOptions pm;
  const std::vector<View> views = test::RenderFrontoParallelPlane(48, 36, 3, kPlaneDepth, 0.25f);
  const std::vector<Problem> problems = AllProblems(3);
  const test::TempDir scratch;
  MemorySink single;
  RunPatchMatchCpu(views, problems, pm, msp, scratch.path(), single);
  test::MemoryExchange exchange;
  MemorySink sinks[2];
  std::vector<std::thread> shards;
  for (int k = 0; k < 2; ++k) {
    shards.emplace_back([&, k] {
      SharedRun run;
      run.exchange = &exchange;
      run.owned = ProblemsOfShard(3, ShardSpec{k, 2});
      run.shard = ShardSpec{k, 2};
      run.timeout_seconds = 120;
      run.name = "shard " + std::to_string(k) + "/2";
      RunPatchMatchCpu(views, problems, pm, msp, scratch / ("shard" + std::to_string(k)), sinks[k],
                       &run);
    });
  }
  for (std::thread& shard : shards) shard.join();
  size_t written = 0;
  for (const auto& entry : single.maps) {
    const MemorySink& owner = sinks[entry.first.first % 2];
    ASSERT_TRUE(owner.maps.count(entry.first)) << entry.first.first << " " << entry.first.second;
    EXPECT_EQ(owner.maps.at(entry.first).first.data, entry.second.first.data);
    EXPECT_EQ(owner.maps.at(entry.first).second.data, entry.second.second.data);
    ++written;
  }
  EXPECT_EQ(sinks[0].maps.size() + sinks[1].maps.size(), written);
  // The sinks say no map is final, so the states stay (a file sink's would go).
  EXPECT_EQ(exchange.Clears(), 0);
}

// A black backdrop (the plane left of x = 0 in the world, dark in every
// view) has nothing to match: with the default black level its pixels get
// no depth, while the lit half is recovered as without a backdrop. Matching
// it (black level 0, open-sky rule off) gives the backdrop the lit half's
// plane carried over.
TEST(PatchMatchCpu, PixelsWithNothingToMatchGetNoDepth) {
  std::vector<View> views = test::RenderFrontoParallelPlane(96, 72, 4, kPlaneDepth, 0.25f);
  for (View& view : views) {
    for (int r = 0; r < view.gray.height; ++r) {
      for (int c = 0; c < view.gray.width; ++c) {
        if (test::PointOnPlaneZ(view.camera, c, r, kPlaneDepth).x >= 0.0f) continue;
        view.gray.At(r, c) = 0.01f * (view.gray.At(r, c) > 0.5f);  // dark: 0 or 1 % of full scale
        for (int ch = 0; ch < 3; ++ch) view.color.At(r, c, ch) = view.gray.At(r, c);
      }
    }
  }
  const auto geometric_depth = [&](double black_level) {
    PatchMatchStereoOptions pm;
    MspStereoOptions msp = WithDeformable();
    msp.num_threads = 2;
    msp.black_level = black_level;
    // The black level alone: the open-sky rule would also empty the backdrop
    // (a blank segment at the border with no edge of its own).
    msp.open_sky = false;
    MemorySink sink;
    const test::TempDir scratch;
    RunPatchMatchCpu(views, AllProblems(4), pm, msp, scratch.path(), sink);
    return sink.maps.at({0, std::string("geometric")}).first;
  };
  const DenseMap depth = geometric_depth(MspStereoOptions().black_level);
  const DenseMap matched = geometric_depth(0.0);
  const int centre = 48;  // world x = 0 in the reference
  int dark = 0, dark_valid = 0, dark_matched = 0, lit = 0, lit_accurate = 0;
  for (int r = 12; r < depth.height - 12; ++r) {
    for (int c = 12; c < depth.width - 12; ++c) {
      if (c < centre - 8) {  // the backdrop's pixels whose whole window is dark
        ++dark;
        dark_valid += depth.At(r, c) > 0.0f;
        dark_matched += matched.At(r, c) > 0.0f;
      } else if (c > centre + 8) {
        ++lit;
        lit_accurate += std::fabs(depth.At(r, c) - kPlaneDepth) < 0.005f * kPlaneDepth;
      }
    }
  }
  EXPECT_EQ(dark_valid, 0);
  EXPECT_GT(dark_matched, dark / 2) << dark_matched << " of " << dark;
  EXPECT_GT(lit_accurate, 0.9 * lit) << lit_accurate << " of " << lit;
}

TEST(PatchMatchCpu, SkipsImagesWithFinalOutputs) {
  const std::vector<View> views = test::RenderFrontoParallelPlane(48, 36, 3, kPlaneDepth, 0.25f);
  PatchMatchStereoOptions pm;
  pm.geom_consistency = false;
  MspStereoOptions msp = WithDeformable();
  MemorySink sink;
  for (int v = 0; v < 3; ++v) sink.done[v] = true;
  const test::TempDir scratch;
  RunPatchMatchCpu(views, AllProblems(3), pm, msp, scratch.path(), sink);
  EXPECT_TRUE(sink.maps.empty());
}

}  // namespace
}  // namespace msp
