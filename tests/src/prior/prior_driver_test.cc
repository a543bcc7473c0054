#include "prior/prior_driver.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

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

}  // namespace
}  // namespace msp
