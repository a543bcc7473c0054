// Edge aggregation of the multi-granularity segmentation prior (docs/method.md
// sections 4.2-4.4, eqs. 4-5): boundary maps B_n of the label layers, the best
// layer S_max of every unreliable pixel, label retention per region, and the
// aggregated segmentation whose boundary map B' confines anchor search. The
// union of all layers' boundaries is the ablation without aggregation.
#pragma once

#include <cstdint>
#include <vector>

#include "base/label_layers.h"
#include "core/prior/best_layer.h"
#include "core/prior/segment_crossing.h"

namespace msp {

// B = tau(M) = {q : Laplacian(M)(q) != 0}: 1 where a 4-neighbour holds another
// label, else 0. Row-major, width x height.
std::vector<uint8_t> ComputeBoundaryMap(const std::vector<int32_t>& labels, int width, int height);
// B_n of every level.
std::vector<std::vector<uint8_t>> ComputeBoundaryMaps(const LabelLayers& layers);
// Pixel-wise OR of boundary maps: the union of all layers' edges ("w/o Agr.").
std::vector<uint8_t> UnionBoundaryMap(const std::vector<std::vector<uint8_t>>& boundaries);

core::BoundaryView MakeBoundaryView(const std::vector<uint8_t>& boundary, int width, int height);

struct BestLayerOptions {
  core::PlaneRansacParams ransac;
  // Random stream of the RANSAC triangles: (seed, image, pass, pixel).
  uint32_t seed = 0;
  uint32_t image = 0;
  uint32_t pass = 0;
  int num_threads = 1;
};

// Eq. 4 for every listed unreliable pixel: the per-layer subsets S_n (the
// anchors whose line from p crosses no pixel of B_n) and their best layers.
// Returns a width x height map of best-layer bit sets (bit n = layer n is
// S_max); 0 for pixels not listed or where no subset can be planarised.
std::vector<uint32_t> ChooseBestLayers(const LabelLayers& layers,
                                       const std::vector<std::vector<uint8_t>>& boundaries,
                                       const std::vector<core::PriorAnchors>& pixels,
                                       const BestLayerOptions& options);

// Eq. 5: region k of layer n (the pixels with label k in level n) is kept iff
// n = argmax_l #{p in region : layer l is a best layer of p}; ties go to the
// coarser layer, so a region without votes is kept only in the coarsest
// level. Label 0 (unlabelled) is never kept. Returns per level a width x
// height map, 1 where the pixel's region is kept.
std::vector<std::vector<uint8_t>> RetainRegions(const LabelLayers& layers,
                                                const std::vector<uint32_t>& best_layers);

// A segmentation on the pixel grid with its boundary map.
struct Segmentation {
  int width = 0;
  int height = 0;
  std::vector<int32_t> labels;  // dense ids >= 0, row-major
  std::vector<uint8_t> edges;   // ComputeBoundaryMap(labels)
};

// The aggregated image sum_n M_n^k over the kept regions: two pixels share a
// label iff they lie in the same kept regions of every level (a level whose
// region is not kept contributes nothing). Its edges are B' of the paper.
Segmentation AggregateRegions(const LabelLayers& layers,
                              const std::vector<std::vector<uint8_t>>& kept);

// Every labelled region of every level kept: the segmentation whose edges are
// the union of all B_n (the ablation "w/o Agr.").
Segmentation UnionOfLayers(const LabelLayers& layers);

}  // namespace msp
