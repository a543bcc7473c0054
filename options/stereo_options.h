// Option structs of msp_stereo. PatchMatchStereoOptions mirrors COLMAP's
// PatchMatchOptions field by field (same names, same defaults), so an existing
// `colmap patch_match_stereo` command line is a valid `msp_stereo` one.
// MspStereoOptions holds this project's own knobs (--MspStereo.<field>).
//
// Each struct names its section (kSection): the option of a field is
// --<kSection>.<field> on the command line and <field> under [<kSection>] in
// an ini file (top-level fields have no section). The parser, Check() and the
// start-up print derive every name from the field itself (option_name.h).
// Fields that COLMAP has but msp_stereo does not use say "accepted, ignored".
#pragma once

#include <string>

#include "core/math/limits.h"

namespace msp {

// Widest matching window (half size) the back-ends support, defined once in
// src/core/math/limits.h next to the other capacities. COLMAP accepts up to 32
// (its CUDA block width) although its kernels handle only 20; Check() uses
// this constant so an accepted value always fits the kernels' window arrays.
using core::kMaxWindowRadius;

// Every --PatchMatchStereo.* option of COLMAP 3.8 (src/mvs/patch_match.h),
// plus num_threads of COLMAP >= 3.10.
struct PatchMatchStereoOptions {
  static constexpr char kSection[] = "PatchMatchStereo";

  // Larger image side in pixels; larger images, their K and the maps are downsized; -1 = full.
  int max_image_size = -1;
  // CUDA devices of the cuda back-end, one worker each ("0,1"; -1 = all devices).
  std::string gpu_index = "-1";
  // Smallest depth (scene units) of the random search; -1 (with depth_max) = from sparse points.
  double depth_min = -1.0;
  // Largest depth (scene units) of the random search; -1 (with depth_min) = from sparse points.
  double depth_max = -1.0;
  // Half size of the NCC matching window in pixels (1..kMaxWindowRadius).
  int window_radius = 5;
  // accepted, ignored: the window sampling step (pixels) is MspStereoOptions::window_step.
  int window_step = 1;
  // Spatial sigma (pixels) of bilateral NCC, only with --MspStereo.bilateral_ncc; <= 0 = radius.
  double sigma_spatial = -1.0;
  // Colour sigma (grey level in [0, 1]) of bilateral NCC, only with --MspStereo.bilateral_ncc.
  double sigma_color = 0.2;
  // Source views drawn per pixel (Monte-Carlo view selection) to form the matching cost.
  int num_samples = 15;
  // accepted, ignored: spread (unitless) of the NCC likelihood of COLMAP's view selection.
  double ncc_sigma = 0.6;
  // Minimum triangulation angle in degrees for __auto__ source-image selection.
  double min_triangulation_angle = 1.0;
  // accepted, ignored: spread (on 1 - cos) of the incident-angle likelihood, as ncc_sigma.
  double incident_angle_sigma = 0.9;
  // accepted, ignored: COLMAP's iteration count; the red-black iterations per pass are
  // MspStereoOptions::advanced_iterations and advanced_finest_iterations.
  int num_iterations = 5;
  // 3 geometric passes per round after the photometric one; writes *.geometric.bin (else only
  // *.photometric.bin).
  bool geom_consistency = true;
  // Weight (unitless) of the reprojection error against the photometric cost (1 - NCC).
  double geom_consistency_regularizer = 0.3;
  // Clamp in pixels of the forward-backward reprojection error in the geometric cost.
  double geom_consistency_max_cost = 3.0;
  // Filter the final depth and normal maps by the filter_* rules below.
  bool filter = true;
  // Filter: smallest NCC (in [-1, 1]) of a source view that counts as consistent.
  double filter_min_ncc = 0.1;
  // Filter: smallest triangulation angle in degrees of a source view that counts as consistent.
  double filter_min_triangulation_angle = 3.0;
  // Filter: number of consistent source views a pixel needs to be kept.
  int filter_min_num_consistent = 2;
  // Filter: largest forward-backward reprojection error in pixels of a consistent source view.
  double filter_geom_consistency_max_cost = 1.0;
  // Memory budget in gigabytes for cached per-image state; beyond it state spills to disk.
  double cache_size = 32.0;
  // Drop missing source images (with a warning) instead of failing.
  bool allow_missing_files = false;
  // accepted, ignored (with a warning): no consistency graphs are written.
  bool write_consistency_graph = false;
  // Worker threads of the CPU back-end and of the CUDA back-end's CPU steps; <= 0 = all cores.
  // COLMAP >= 3.10's thread count (its -1 = all cores, too).
  int num_threads = -1;
};

// This project's own options (--MspStereo.*): first those a user sets, then
// the advanced ones (--MspStereo.advanced_*, listed by --help_all only): the
// method's numeric internals and its coarse-to-fine schedule, whose defaults
// are the paper's or measured (BENCHMARKS.md) and which ablations and
// benchmarks vary. The help texts (option_parser.cc) say what each does.
struct MspStereoOptions {
  static constexpr char kSection[] = "MspStereo";

  // "auto" (cuda when a CUDA device is present, else cpu), "cpu" or "cuda".
  std::string backend = "auto";
  // "K/N": this process computes the reference images of problems K, K+N, K+2N, ... of N
  // processes sharing the workspace, which exchange each pass's states through
  // stereo/msp_shared (docs/cluster.md); "" = every image in this process.
  std::string shard = "";
  // File of reference image names (as in images/, one per line) this process computes, a shard
  // of one's choosing; "" = none. Not with `shard`.
  std::string image_list = "";
  // Seconds a shard waits at a pass barrier for the other processes' images before it stops.
  double shard_timeout = 86400.0;
  // Folder of per-image segmentation mask layers; "" = <workspace>/masks.
  std::string mask_path = "";
  // Pixels whose whole matching window is darker than this (grey, 0..1 of full scale) have
  // nothing to match: no plane, never scored, empty in the maps; 0 = every pixel is matched.
  double black_level = 0.03;
  // Pixel step between window samples, 1 or 2 (paper: 2); replaces --PatchMatchStereo.window_step.
  int window_step = 2;
  // Bilateral NCC weights (COLMAP's sigma_spatial, sigma_color) instead of APD-MVS's uniform ones.
  bool bilateral_ncc = false;
  // Deformable patches of APD-MVS, and with them every part MSP-MVS adds (prior, eq. 7,
  // clustering, 3D optimization): unreliable pixels match over reliable anchors. Off by default:
  // it has not paid on the benchmarks (docs/method.md section 9); false = the conventional core.
  bool deformable = false;
  // After each pass, matched edge pixels give each colour segment a plane that its textureless
  // pixels take (docs/method.md section 2.10); false = no segment planes.
  bool segment_planes = true;
  // In geometric passes a segment's plane is offered only when the other views' depth maps
  // confirm it at least half as often as the planes its pixels hold (docs/method.md section 2.10).
  bool segment_plane_confirmation = false;
  // A segment's plane counts only the support that is its own: not the border where a neighbour
  // with the same plane ends (a window's outline, a roofline) (docs/method.md section 2.10).
  bool segment_plane_own_support = true;
  // Untextured segments open to the image border with no evidence of a depth of their own are
  // left empty: the sky (docs/method.md section 2.11). Needs segment_planes.
  bool open_sky = true;
  // Normals of the final maps from the plane fitted to the depths around each pixel, instead of
  // the sweeps' normals, which scatter on weak texture (docs/method.md section 2.9).
  bool normals_from_depth = true;
  // In geometric passes, planes of triangles between the pixels the other views confirm, inside
  // one colour segment, offered to the unconfirmed pixels within (docs/method.md section 2.12).
  bool planar_prior = true;
  // In geometric passes, planes fitted to each colour segment's confirmed pixels, offered to its
  // weakly textured pixels within 3 % of one (docs/method.md section 2.13).
  bool consensus_planes = true;
  // Mask files given, a matching window keeps only the samples in its centre's region of their
  // coarsest layer, the objects (docs/method.md section 2.3).
  bool region_windows = true;
  // Depth range of a reference image from the sparse points it or any of its sources observes
  // that lie in front of it and inside its image (COLMAP's percentile rule on more points);
  // false = its own observations only, as COLMAP.
  bool depth_range_from_sources = false;
  // The final filter judges a weakly textured pixel by geometric agreement alone (no NCC test).
  bool filter_textureless_by_geometry = true;
  // The final filter's geometric test: a source agrees when its depth map holds the pixel's point
  // within this relative depth; 0 = COLMAP's reprojection error in pixels.
  double filter_max_depth_error = 0.01;
  // The final filter also keeps a pixel one source alone confirms with the depth within this
  // relative error; 0 = at least filter_min_num_consistent sources, as COLMAP.
  double filter_single_view_depth_error = 0.005;
  // Geometric passes measure a source's disagreement in depth: this share of the depth costs what
  // one pixel of reprojection error does; 0 = COLMAP's reprojection error in pixels.
  double geom_consistency_depth_error = 0.01;
  // The weight of the geometric term in depth (geom_consistency_depth_error > 0), in place of
  // --PatchMatchStereo.geom_consistency_regularizer, COLMAP's weight of its reprojection error
  // (which stays its default, 0.3, and weighs the term in pixels).
  double geom_consistency_depth_weight = 0.2;
  // Adaptive equidistribution (eq. 7, docs/method.md section 5): re-cut each unreliable pixel's
  // 8 anchor sectors so that each faces about as many reliable pixels; false = fixed 45-degree
  // sectors ("w/o Eqd.").
  bool equidistribution = true;
  // Segmentation prior (docs/method.md section 4): anchors never cross its edges; "w/o Mul.".
  bool segmentation_prior = true;
  // Aggregate layers per region by best anchor subsets (eqs. 4-5); false = union ("w/o Agr.").
  bool edge_aggregation = true;
  // Refine the aggregated edges with the colour/depth CRF (eq. 6); false = "w/o Ref.".
  bool edge_refinement = true;
  // Add label layers segmented from the current depth and normal maps to the embedded colour
  // layers (never to mask files), so the prior sees depth edges between alike colours; false =
  // colour layers only.
  bool geometry_layers = true;
  // Graph segmenter of the embedded layers and of segment planes: "opencv" (OpenCV contrib's
  // ximgproc) or "embedded" (this project's).
  std::string segmenter = "opencv";
  // Write pictures to <workspace>/stereo/prior_previews/: <image>.{depth,normal,error}.png of the
  // final maps (error with a ground_truth/ folder), <image>.png of the prior's edges.
  bool write_previews = false;
  // Disassemble-clustering (docs/method.md section 6): every RANSAC inlier is an anchor, DBSCAN
  // clusters of them are the deformable patch's sub-patch groups; false = APD's 8 anchors.
  bool disassemble_clustering = true;
  // Disparity-sampling synergistic 3D optimization (docs/method.md section 7): the sampling pixels
  // of the deformable patch's sub-patches at random, the best of several solutions by eq. 9.
  bool synergistic_optimization = true;

  // --- Advanced: the coarse-to-fine schedule (docs/method.md section 1) ---
  // Coarse-to-fine rounds halve the images until the larger side is at most this (pixels).
  int advanced_coarsest_image_size = 80;
  // Red-black iterations per pass in every round but the finest of several (APD: 3), and in the
  // finest round of a run with several rounds.
  int advanced_iterations = 3;
  int advanced_finest_iterations = 1;
  // Geometric passes per round after the photometric one (1..3; APD: 3), in the coarser rounds
  // and in the finest round of a run with several rounds.
  int advanced_geometric_passes = 3;
  int advanced_finest_geometric_passes = 3;
  // Rounds after the first whose images' larger side is at least this many pixels restore detail
  // as the finest round does (the advanced_finest_* schedule); 0 = the finest round only. The
  // planes are found up to 300-599 px, where a 640x480 run finds them (docs/method.md 1.2).
  int advanced_restoring_image_size = 600;
  // Disparity pixels each side of the local refinement's sweep in the finest round of several
  // (1..5; the coarser rounds sweep 5): on a flat cost a wider sweep lets the noise move the depth.
  int advanced_finest_refine_radius = 2;
  // In the finest round of several, weakly textured pixels whose neighbours continue their plane
  // keep the plane carried up: no sweep or local refinement moves it (flat noise at full size).
  bool advanced_finest_hold_weak_texture = true;
  // Rounds whose images' larger side exceeds this many pixels run the conventional sweeps, not
  // the deformable step; 0 = no limit.
  int advanced_deformable_max_image_size = 80;
  // The finest round of a run with several rounds runs the deformable step; false = conventional.
  bool advanced_finest_deformable = false;
  // In the finest round of a run with several rounds, propagation candidates are scored only on
  // the views of the pixel's last selection (the views that carry its weight); false = on all.
  bool advanced_weighted_views_only = true;
  // Carry planes up a round by an image-guided joint-bilateral vote (ACMM); false = nearest.
  bool advanced_joint_bilateral_upsampling = true;

  // --- Advanced: numeric internals of the deformable step (docs/method.md sections 3-7) ---
  // Cost (1 - NCC, in [0, 2]) above which the lowest cost-curve minimum is unreliable (APD: 0.5).
  double advanced_reliable_max_cost = 0.5;
  // Cost (1 - NCC) at or below which a single curve minimum is reliable (APD: 0.15).
  double advanced_reliable_single_cost = 0.15;
  // Cost (1 - NCC) every other minimum must lie above the lowest to be reliable (APD: 0.2).
  double advanced_reliable_min_spread = 0.2;
  // Anchor search range in pixels of the current round (APD: 100).
  int advanced_anchor_max_distance = 100;
  // Re-cuts of the equidistribution per pixel (1..3); each casts up to 8 more boundary rays.
  int advanced_equidistribution_iterations = 2;
  // Label layers the embedded segmenter builds for an image without mask files (paper: 3).
  int advanced_num_mask_levels = 3;
  // CRF (eq. 6) depth bandwidth alpha, as a fraction of the depth range.
  double advanced_crf_alpha = 0.02;
  // CRF (eq. 6) colour bandwidth beta on |I_p . I_q - 1| of normalised RGB (unitless).
  double advanced_crf_beta = 0.05;
  // CRF probability (in (0, 1)) that the unary gives the aggregated label.
  double advanced_crf_unary_confidence = 0.7;
  // CRF mean-field iterations (count).
  int advanced_crf_iterations = 5;
  // DBSCAN eta: neighbours (the point not counted) within dbscan_gamma that make a core anchor.
  int advanced_dbscan_eta = 2;
  // DBSCAN gamma in pixels of the current round; 0 = max(3, 0.25 x median anchor distance to p).
  double advanced_dbscan_gamma = 0.0;
  // J: sampling solutions drawn per optimization (the one in use competes with them).
  int advanced_sampling_solutions = 6;
  // The paper's iterative local search: in every iteration the solution in use competes with J
  // perturbations of itself (one sub-patch re-sampled each); false = J independent draws once per
  // pass that replace it.
  bool advanced_sampling_local_search = true;
  // mu: disparities of a cost profile (odd).
  int advanced_disparity_samples = 5;
  // delta: step between the profile's disparities, in pixels of disparity.
  double advanced_disparity_step = 1.0;
  // omega: weight of eq. 9's variance term sum (c_i - c_bar)^-2; 0 = no variance term.
  double advanced_variance_weight = 0.01;
  // Eq. 9 with the sum of the profile's costs; false = the variance term alone.
  bool advanced_profile_cost_term = true;

  // Not options: what the back-ends read of COLMAP's options, which the parser copies here
  // (the option names are COLMAP's, each concept has one).
  // The seed (>= 0) of the counter-based random generator, which a run is a pure function of:
  // --random_seed.
  int seed = 0;
  // Worker threads of the CPU back-end; <= 0 = all cores: --PatchMatchStereo.num_threads.
  int num_threads = -1;
};

// Everything the msp_stereo command needs; top-level options have no section.
struct StereoCommandOptions {
  static constexpr char kSection[] = "";

  // Dense workspace folder written by `colmap image_undistorter` (required).
  std::string workspace_path;
  // COLMAP or PMVS (upper-cased by the parser); PMVS workspaces are refused with a message.
  std::string workspace_format = "COLMAP";
  // accepted, ignored: option file name of a PMVS workspace, which msp_stereo refuses.
  std::string pmvs_option_name = "option-all";
  // Problem file to use instead of <workspace>/stereo/patch-match.cfg; "" = that file.
  std::string config_path;
  // Ini file with [PatchMatchStereo] / [MspStereo] sections; the command line overrides it.
  std::string project_path;
  // COLMAP's global seed (>= 0), the seed of the random numbers; the parser copies it into
  // MspStereoOptions::seed, which the back-ends read.
  int random_seed = 0;
  // accepted, ignored: msp_stereo logs to stdout and reports errors on stderr.
  bool log_to_stderr = false;
  // COLMAP's glog verbosity (-v): a log line of level n shows when n <= log_level
  // (base/log.h); COLMAP's default 2 shows them all.
  int log_level = 2;
  PatchMatchStereoOptions patch_match;  // --PatchMatchStereo.*
  MspStereoOptions msp;                 // --MspStereo.*
};

}  // namespace msp
