// Option structs of msp_stereo. PatchMatchStereoOptions mirrors COLMAP's
// PatchMatchOptions field by field (same names, same defaults), so an existing
// `colmap patch_match_stereo` command line is a valid `msp_stereo` one.
// MspStereoOptions holds this project's own knobs (--MspStereo.<field>).
#pragma once

#include <string>

#include "core/math/limits.h"

namespace msp {

// Widest matching window (half size) the back-ends support, defined once in
// src/core/math/limits.h next to the other capacities. COLMAP accepts up to 32
// (its CUDA block width) although its kernels handle only 20; Check() uses
// this constant so an accepted value always fits the kernels' window arrays.
using core::kMaxWindowRadius;

// Every --PatchMatchStereo.* option of COLMAP 3.8 (src/mvs/patch_match.h).
struct PatchMatchStereoOptions {
  // Maximum image side; larger images (and K) are downsized, and so are the maps.
  int max_image_size = -1;
  // CUDA devices; -1 = all. Only meaningful with the CUDA back-end.
  std::string gpu_index = "-1";
  // Depth range; -1 = from the sparse model's track observations.
  double depth_min = -1.0;
  double depth_max = -1.0;
  // Half window size of the matching window, and the sampling step inside it.
  int window_radius = 5;
  int window_step = 1;
  // Bilateral NCC weights; sigma_spatial <= 0 means window_radius.
  double sigma_spatial = -1.0;
  double sigma_color = 0.2;
  // Monte-Carlo view samples per pixel.
  int num_samples = 15;
  double ncc_sigma = 0.6;
  // Minimum triangulation angle (degrees) for __auto__ source selection.
  double min_triangulation_angle = 1.0;
  double incident_angle_sigma = 0.9;
  int num_iterations = 5;
  bool geom_consistency = true;
  double geom_consistency_regularizer = 0.3;
  double geom_consistency_max_cost = 3.0;
  bool filter = true;
  double filter_min_ncc = 0.1;
  double filter_min_triangulation_angle = 3.0;
  int filter_min_num_consistent = 2;
  double filter_geom_consistency_max_cost = 1.0;
  // Memory budget in gigabytes for cached per-image state.
  double cache_size = 32.0;
  bool allow_missing_files = false;
  bool write_consistency_graph = false;
};

// This project's own options (--MspStereo.*).
struct MspStereoOptions {
  // "cpu" or "cuda" ("cuda" needs a build with CUDA and a GPU).
  std::string backend = "cpu";
  // Seed of the counter-based random generator; a run is a pure function of it.
  int seed = 0;
  // Worker threads of the CPU back-end; <= 0 = all cores.
  int num_threads = -1;
  // Folder of per-image segmentation mask layers; "" = <workspace>/masks.
  std::string mask_path = "";
  // Rounds of the coarse-to-fine schedule halve the images until the larger
  // side is at most this many pixels (APD-MVS: 1000).
  int coarsest_image_size = 1000;
  // Sampling step inside the matching window. The paper matches every other
  // row and column of an 11x11 window; --PatchMatchStereo.window_step (COLMAP's
  // default 1) is not used, so that COLMAP command lines keep this speed.
  int window_step = 2;
  // COLMAP's bilateral NCC weights (sigma_spatial, sigma_color) instead of the
  // uniform weights of APD-MVS.
  bool bilateral_ncc = false;
  // Deformable patch matching of the APD-MVS baseline (algorithm.md 2): after
  // each pass pixels are classified reliable / unreliable from their disparity
  // cost curve, and unreliable pixels match with a patch deformed over reliable
  // anchors. false = the conventional PatchMatch core alone.
  bool deformable = true;
  // Reliability thresholds on the lowest minimum of the cost curve (1 - NCC):
  // above reliable_max_cost it is unreliable; a single minimum is reliable at
  // or below reliable_single_cost; with several, every other minimum must lie
  // more than reliable_min_spread above it (APD: 0.5, 0.15, 0.2).
  double reliable_max_cost = 0.5;
  double reliable_single_cost = 0.15;
  double reliable_min_spread = 0.2;
  // Anchor search range in pixels of the current round (APD: 100).
  int anchor_max_distance = 100;
  // Multi-granularity segmentation prior (paper "Multi-granularity
  // Segmentation Prior"; algorithm.md 3.1-3.2): anchors must not cross the
  // depth edges it finds. false = the ablation "w/o Mul.".
  bool segmentation_prior = true;
  // Aggregate the layers per region by their best anchor subsets (eqs. 4-5);
  // false = the union of all layers' boundaries ("w/o Agr.").
  bool edge_aggregation = true;
  // Refine the aggregated edges with the colour/depth CRF (eq. 6); false =
  // "w/o Ref.".
  bool edge_refinement = true;
  // Label layers the embedded segmenter builds when an image has no mask
  // files (paper: 3, scene / instance / feature level). Mask files set their
  // own count.
  int num_mask_levels = 3;
  // Write <workspace>/stereo/prior_previews/<image>.png: the aggregated (red)
  // and refined (green) edges over the image.
  bool write_previews = false;
  // CRF of eq. 6: depth bandwidth alpha as a fraction of the depth range,
  // colour bandwidth beta on |I_p . I_q - 1|, probability of the aggregated
  // label in the unary, mean-field iterations t = 1..crf_iterations.
  double crf_alpha = 0.02;
  double crf_beta = 0.05;
  double crf_unary_confidence = 0.7;
  int crf_iterations = 5;
};

// Everything the msp_stereo command needs.
struct StereoCommandOptions {
  std::string workspace_path;
  std::string workspace_format = "COLMAP";
  std::string pmvs_option_name = "option-all";
  std::string config_path;
  std::string project_path;
  PatchMatchStereoOptions patch_match;
  MspStereoOptions msp;
};

}  // namespace msp
