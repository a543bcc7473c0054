// Geometry label layers of the segmentation prior (docs/method.md section 4.1):
// graph segmentation (graph_segmentation.h) of the current depth and normal
// maps of an image, so that the aggregated edges B' (eq. 5) can follow depth
// edges and creases between surfaces of alike colour, which no colour layer
// has. Recomputed after every pass that runs the prior, since the maps
// change; added after the colour layers of the embedded segmenter as further
// granularities of eqs. 4-5 (never to mask-file layers).
#pragma once

#include <cstdint>
#include <vector>

#include "base/dense_map.h"
#include "base/label_layers.h"
#include "core/prior/prior_limits.h"
#include "prior/graph_segmentation.h"

namespace msp {

// The scale of the geometry layer for a width x height map.
GraphSegmentationScale GeometryScale(int width, int height);

// The feature image of the geometry layers (core/prior/geometry_feature.h)
// of a depth map (1 channel, 0 = none) and its normal map (3 channels, unit
// normals). A pixel without depth takes the features of its nearest pixel
// with one, so a hole draws no boundary of its own; a map without any
// depth gives constant features.
DenseMap GeometryFeatureImage(const DenseMap& depth, const DenseMap& normal, int num_threads);

// The core::kNumGeometryLayers label layers of the maps.
LabelLayers SegmentGeometry(const DenseMap& depth, const DenseMap& normal, Segmenter segmenter,
                            int num_threads);

// `colour` followed by `geometry` (same size): the layers eqs. 4-5 aggregate.
LabelLayers AppendLayers(const LabelLayers& colour, const LabelLayers& geometry);

}  // namespace msp
