#include "prior/prior_driver.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "prior/multiscale_segmentation.h"

namespace msp {
namespace {

// 4x3: a vertical split and a horizontal split; their union has four quadrants.
LabelLayers TwoSplits() {
  LabelLayers layers;
  layers.width = 4;
  layers.height = 3;
  layers.levels = {{1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2}, {4, 4, 4, 4, 4, 4, 4, 4, 6, 6, 6, 6}};
  return layers;
}

// The prior with neither aggregation nor refinement: the union of the layers.
MspStereoOptions UnionOnly() {
  MspStereoOptions options;
  options.edge_aggregation = false;
  options.edge_refinement = false;
  options.num_threads = 1;
  return options;
}

TEST(PriorDriver, PackedEdgesKeepTheirThreeMapsApart) {
  SegmentationPriorResult result;
  result.edges = {1, 0, 1, 0};
  result.aggregated.edges = {1, 1, 0, 0};
  result.refined.edges = {1, 0, 1, 1};
  const std::vector<uint8_t> packed = PackPriorEdges(result);
  EXPECT_EQ(UnpackEdgeBit(packed, kConfiningEdge), result.edges);
  EXPECT_EQ(UnpackEdgeBit(packed, kAggregatedEdge), result.aggregated.edges);
  EXPECT_EQ(UnpackEdgeBit(packed, kRefinedEdge), result.refined.edges);
  // Without refinement the refined bit stays clear.
  result.refined.edges.clear();
  EXPECT_EQ(UnpackEdgeBit(PackPriorEdges(result), kRefinedEdge), std::vector<uint8_t>(4, 0));
}

TEST(PriorDriver, WithoutAggregationOrRefinementTheEdgesAreTheUnionOfTheLayers) {
  const LabelLayers layers = TwoSplits();
  const DenseMap color(layers.width, layers.height, 3, 0.5f);
  PriorPassInput input;
  input.color = &color;
  const SegmentationPriorResult result = RunSegmentationPrior(layers, input, UnionOnly());
  EXPECT_EQ(result.edges, UnionOfLayers(layers).edges);
  EXPECT_EQ(result.aggregated.edges, result.edges);
  EXPECT_TRUE(result.refined.edges.empty());
}

TEST(PriorDriver, RunsOnTheMaskFileLayersAndCountsItsCalls) {
  std::vector<View> views(1);
  views[0].name = "a.png";
  views[0].mask_layers.source = LabelSource::kMaskFiles;
  views[0].mask_layers.layers = TwoSplits();
  const DenseMap color(4, 3, 3, 0.5f);
  const std::vector<core::PriorAnchors> anchors;
  PriorPassInput input;
  input.view = 0;
  input.color = &color;
  input.anchors = &anchors;
  PriorDriver driver(views, UnionOnly(), /*num_threads=*/1);
  driver.StartRound();
  const std::vector<uint8_t> packed = driver.Run(input);
  EXPECT_EQ(UnpackEdgeBit(packed, kConfiningEdge), UnionOfLayers(TwoSplits()).edges);
  EXPECT_EQ(UnpackEdgeBit(packed, kAggregatedEdge), UnionOfLayers(TwoSplits()).edges);
  EXPECT_EQ(driver.NumCalls(), 1);
  // Without the anchors the driver refuses to run.
  input.anchors = nullptr;
  EXPECT_THROW(driver.Run(input), std::logic_error);
}

// A uniform grey image with a box standing 10 % proud of the wall behind it:
// the box's outline is a depth edge the colour layers cannot see.
struct BoxScene {
  static constexpr int kWidth = 32, kHeight = 24;
  DenseMap color{kWidth, kHeight, 3, 0.5f};
  DenseMap depth{kWidth, kHeight, 1, 2.0f};
  DenseMap normal{kWidth, kHeight, 3, 0.0f};
  BoxScene() {
    for (int row = 8; row < 16; ++row) {
      for (int col = 10; col < 22; ++col) depth.At(row, col) = 1.8f;
    }
    for (int i = 0; i < kWidth * kHeight; ++i) normal.Plane(2)[i] = -1.0f;
  }
  bool OnBoxOutline(int row, int col) const {
    const bool in = depth.At(row, col) < 2.0f;
    const int dr[4] = {0, 0, 1, -1}, dc[4] = {1, -1, 0, 0};
    for (int k = 0; k < 4; ++k) {
      const int r = row + dr[k], c = col + dc[k];
      if (r >= 0 && c >= 0 && r < kHeight && c < kWidth && (depth.At(r, c) < 2.0f) != in) {
        return true;
      }
    }
    return false;
  }
};

std::vector<uint8_t> RunOnce(const std::vector<View>& views, const MspStereoOptions& options,
                             const BoxScene& scene, bool give_maps) {
  const std::vector<core::PriorAnchors> anchors;
  PriorPassInput input;
  input.view = 0;
  input.color = &scene.color;
  input.anchors = &anchors;
  if (give_maps) {
    input.geometry_depth = &scene.depth;
    input.geometry_normal = &scene.normal;
  }
  PriorDriver driver(views, options, /*num_threads=*/1);
  driver.StartRound();
  return driver.Run(input);
}

// With the embedded segmenter the geometry layers add the box's outline to
// the union of the layers; switched off, the maps are ignored and the edges
// are bit for bit those of the colour layers alone (the previous behaviour).
TEST(PriorDriver, GeometryLayersAddDepthEdgesAndOffIsTheColourOnlyPrior) {
  const BoxScene scene;
  std::vector<View> views(1);
  views[0].name = "a.png";
  for (const char* segmenter : {"opencv", "embedded"}) {
    SCOPED_TRACE(segmenter);
    MspStereoOptions options = UnionOnly();
    options.segmenter = segmenter;
    const std::vector<uint8_t> colour_only = RunOnce(views, options, scene, false);
    EXPECT_EQ(UnpackEdgeBit(colour_only, kConfiningEdge),
              UnionOfLayers(SegmentMultiscale(scene.color, options.advanced_num_mask_levels,
                                              SegmenterFromName(segmenter)))
                  .edges);
    const std::vector<uint8_t> with_geometry = RunOnce(views, options, scene, true);
    for (int row = 0; row < BoxScene::kHeight; ++row) {
      for (int col = 0; col < BoxScene::kWidth; ++col) {
        const size_t i = static_cast<size_t>(row) * BoxScene::kWidth + col;
        EXPECT_EQ((with_geometry[i] & kConfiningEdge) != 0, scene.OnBoxOutline(row, col))
            << row << " " << col;
      }
    }
    options.geometry_layers = false;
    EXPECT_EQ(RunOnce(views, options, scene, true), colour_only);
  }
}

// Mask files stay authoritative: no geometry layers are added to them.
TEST(PriorDriver, MaskFileLayersGetNoGeometryLayers) {
  const BoxScene scene;
  std::vector<View> views(1);
  views[0].name = "a.png";
  views[0].mask_layers.source = LabelSource::kMaskFiles;
  views[0].mask_layers.layers.width = BoxScene::kWidth;
  views[0].mask_layers.layers.height = BoxScene::kHeight;
  views[0].mask_layers.layers.levels.assign(
      1, std::vector<int32_t>(BoxScene::kWidth * BoxScene::kHeight, 1));
  const std::vector<uint8_t> packed = RunOnce(views, UnionOnly(), scene, true);
  EXPECT_EQ(packed, std::vector<uint8_t>(packed.size(), 0));
}

// Layers beyond the driver's budget are made again at each call: the edges of
// every call are those of a driver that keeps them all.
TEST(PriorDriver, LayersBeyondTheBudgetAreMadeAgainWithTheSameEdges) {
  BoxScene scene;
  for (int row = 8; row < 16; ++row) {
    for (int col = 10; col < 22; ++col) scene.color.At(row, col, 0) = 0.9f;
  }
  BoxScene other;
  for (int row = 0; row < 12; ++row) {
    for (int col = 0; col < BoxScene::kWidth; ++col) other.color.At(row, col, 2) = 0.1f;
  }
  std::vector<View> views(2);
  views[0].name = "a.png";
  views[1].name = "b.png";
  const std::vector<core::PriorAnchors> anchors;
  auto run = [&](size_t budget) {
    PriorDriver driver(views, UnionOnly(), /*num_threads=*/1, budget);
    std::vector<std::vector<uint8_t>> edges;
    driver.StartRound();
    for (int pass = 0; pass < 2; ++pass) {
      for (int view = 0; view < 2; ++view) {
        PriorPassInput input;
        input.view = view;
        input.color = view == 0 ? &scene.color : &other.color;
        input.anchors = &anchors;
        edges.push_back(driver.Run(input));
      }
    }
    return edges;
  };
  const std::vector<std::vector<uint8_t>> kept = run(SIZE_MAX);
  EXPECT_NE(kept[0], kept[1]);
  const size_t one_image =
      BoxScene::kWidth * BoxScene::kHeight * sizeof(int32_t) * UnionOnly().advanced_num_mask_levels;
  EXPECT_EQ(run(0), kept);
  EXPECT_EQ(run(one_image), kept);
}

}  // namespace
}  // namespace msp
