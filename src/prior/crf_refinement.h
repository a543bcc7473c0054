// Edge refinement of the aggregated segmentation by a CRF (paper eq. 6):
// mean-field inference on the pixel grid with a Potts pairwise potential
//   psi_p(l_i, l_j) = mu(l_i, l_j) exp(-(t |D_p - D_q| / alpha
//                                        + (1/t) |I_p . I_q - 1| / beta)),
// t the mean-field iteration (colour dominates early, depth later), D the
// current depth, I the normalised RGB colour, and a unary from the aggregated
// labels (the energy of the supplement's eq. 10). Output: the refined labels and their
// depth-edge map.
#pragma once

#include "base/dense_map.h"
#include "prior/segmentation_prior.h"

namespace msp {

struct CrfOptions {
  // Mean-field iterations (the paper's t runs 1..iterations).
  int iterations = 5;
  // Depth bandwidth alpha as a fraction of the depth range (max - min).
  float alpha_relative = 0.02f;
  // Colour bandwidth beta on 1 - cos(angle between normalised RGB colours).
  float beta = 0.05f;
  // Probability the unary gives the aggregated label; the rest is shared by
  // the other labels present around the pixel.
  float unary_confidence = 0.7f;
  int num_threads = 1;
};

// Refines `aggregated` (labels of AggregateRegions or UnionOfLayers) on the
// colour image `color` (3 planes RGB in [0, 1], same size). `depth` (1 plane,
// 0 = no depth) may be null or empty: then only the colour term is used, as
// at the first round; pixel pairs where either depth is 0 also use colour
// only. A label can move at most the window radius (kCrfWindowRadius) from
// where the aggregation put it; pixels whose window holds a single label keep
// it without work, so the cost is O(pixels near edges x window x labels there).
Segmentation RefineSegmentationCrf(const Segmentation& aggregated, const DenseMap& color,
                                   const DenseMap* depth, float depth_min, float depth_max,
                                   const CrfOptions& options);

}  // namespace msp
