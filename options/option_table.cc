#include "options/option_table.h"

#include <string>

#include "core/deformable/deformable_limits.h"
#include "core/deformable/synergistic_optimization.h"
#include "core/prior/prior_limits.h"
#include "options/option_name.h"

namespace msp {

namespace po = boost::program_options;

void OptionTable::AddToGroup(const std::string& name, const po::value_semantic* value,
                             const std::string& help, OptionGroup group) {
  const std::string advanced = std::string(MspStereoOptions::kSection) + "." + kAdvancedPrefix;
  if (name.compare(0, advanced.size(), advanced) == 0) {
    group = OptionGroup::kAdvanced;
    AddRenamed(std::string(MspStereoOptions::kSection) + "." + name.substr(advanced.size()), name);
  }
  po::options_description& description = group == OptionGroup::kAdvanced  ? advanced_
                                         : group == OptionGroup::kIgnored ? ignored_
                                                                          : common_;
  description.add_options()(name.c_str(), value, help.c_str());
}

void OptionTable::AddNoDefault(const std::string& name, std::string* field,
                               const std::string& help) {
  common_.add_options()(name.c_str(), po::value<std::string>(field), help.c_str());
  Remember(name, field);
}

void OptionTable::AddRenamed(const std::string& old_name, const std::string& new_name) {
  renamed_.emplace_back(old_name, new_name);
}

po::options_description OptionTable::All() const {
  po::options_description all;
  all.add(common_).add(advanced_).add(ignored_);
  return all;
}

const po::options_description& OptionTable::Description(OptionGroup group) const {
  return group == OptionGroup::kAdvanced  ? advanced_
         : group == OptionGroup::kIgnored ? ignored_
                                          : common_;
}

std::string OptionTable::RenamedTo(const std::string& name) const {
  for (const auto& [old_name, new_name] : renamed_) {
    if (old_name == name) return new_name;
  }
  return "";
}

namespace {

// Registers `options.field` under the name its field gives it (option_name.h),
// so no option name is typed here.
#define MSP_ADD_OPTION(table, options, field, help) \
  (table)->Visit(MSP_OPTION_NAME(options, field), &(options).field, help, OptionGroup::kCommon)
#define MSP_ADD_OPTION_NO_DEFAULT(table, options, field, help) \
  (table)->AddNoDefault(MSP_OPTION_NAME(options, field), &(options).field, help)
// A COLMAP option this program accepts and ignores (listed by --help_all only).
#define MSP_ADD_IGNORED_OPTION(table, options, field, help) \
  (table)->Visit(MSP_OPTION_NAME(options, field), &(options).field, help, OptionGroup::kIgnored)

// The options of each struct, in usage order. Each help text is the one
// description of its option: --help prints it, and the README's option table
// is generated from --help_all (tools/options_table.py). Help texts of the
// PatchMatchStereo options follow the field comments of COLMAP's
// PatchMatchOptions, then say how this program honours them; a help text that
// points at another option spells it from its field too (MSP_OPTION_FLAG).
void DefineTopLevelOptions(StereoCommandOptions* o, OptionTable* t) {
  MSP_ADD_OPTION_NO_DEFAULT(t, *o, workspace_path,
                            "Dense workspace written by `colmap image_undistorter` (required).");
  MSP_ADD_OPTION(t, *o, workspace_format,
                 "{COLMAP, PMVS}. Only COLMAP workspaces can be processed; PMVS ones are refused "
                 "with a message.");
  MSP_ADD_IGNORED_OPTION(t, *o, pmvs_option_name,
                         "Option file name of a PMVS workspace, which msp_stereo refuses.");
  MSP_ADD_OPTION(t, *o, config_path,
                 "Problem file to use instead of <workspace>/stereo/patch-match.cfg.");
  MSP_ADD_OPTION_NO_DEFAULT(
      t, *o, project_path,
      "Ini file with [PatchMatchStereo] and [MspStereo] sections (a COLMAP project.ini "
      "works; other sections are skipped); options given on the command line override it.");
  MSP_ADD_OPTION(t, *o, random_seed,
                 "Seed (>= 0) of the counter-based random numbers, COLMAP's option: a run is a "
                 "pure function of it, the same for any thread count and shard split.");
  MSP_ADD_IGNORED_OPTION(t, *o, log_to_stderr, "The log goes to stdout, errors to stderr.");
  MSP_ADD_OPTION(t, *o, log_level,
                 "Verbosity, as COLMAP's (glog's -v): 2 = every line, 1 = no per-step figures "
                 "(one line per image and pass with the running total and ETA), 0 = no "
                 "per-image lines either (the start, warnings, errors and the final summary).");
}

void DefinePatchMatchStereoOptions(PatchMatchStereoOptions* p, OptionVisitor* t) {
  const std::string bilateral_ncc = MSP_OPTION_FLAG_OF(MspStereoOptions, bilateral_ncc);
  MSP_ADD_OPTION(t, *p, max_image_size,
                 "Maximum image size in either dimension; larger images, their intrinsics and the "
                 "output maps are downsized as COLMAP's Downsize does. -1 = full size.");
  MSP_ADD_OPTION(t, *p, gpu_index,
                 "CUDA device indices separated by commas, e.g. \"0,1\"; -1 = all devices. One "
                 "worker per listed GPU, the images spread over them; read by the cuda back-end "
                 "only (see " +
                     MSP_OPTION_FLAG_OF(MspStereoOptions, backend) +
                     "; with cpu a warning says it is ignored).");
  MSP_ADD_OPTION(t, *p, depth_min,
                 "Minimum depth of the random search; -1 (with depth_max -1) = from the sparse "
                 "points of each image (1st percentile x 0.75).");
  MSP_ADD_OPTION(t, *p, depth_max,
                 "Maximum depth of the random search; -1 (with depth_min -1) = from the sparse "
                 "points of each image (99th percentile x 1.25).");
  MSP_ADD_OPTION(t, *p, window_radius,
                 "Half window size of the photo-consistency (NCC) window, at most " +
                     std::to_string(kMaxWindowRadius) + ".");
  MSP_ADD_IGNORED_OPTION(t, *p, window_step,
                         "Step between the pixels sampled inside the window; the step is " +
                             MSP_OPTION_FLAG_OF(MspStereoOptions, window_step) +
                             " (a COLMAP project.ini lists window_step=1, which must not make "
                             "every run four times slower).");
  MSP_ADD_OPTION(t, *p, sigma_spatial,
                 "Spatial sigma of the bilateral NCC weights; <= 0 = window_radius. Used with " +
                     bilateral_ncc + " true.");
  MSP_ADD_OPTION(
      t, *p, sigma_color,
      "Colour sigma of the bilateral NCC weights. Used with " + bilateral_ncc + " true.");
  MSP_ADD_OPTION(t, *p, num_samples,
                 "Number of source views sampled per pixel to compute the matching cost: the "
                 "Monte-Carlo view draws of ACMM's view selection.");
  MSP_ADD_IGNORED_OPTION(t, *p, ncc_sigma,
                         "Spread of the NCC likelihood of COLMAP's view selection; view selection "
                         "follows ACMM.");
  MSP_ADD_OPTION(t, *p, min_triangulation_angle,
                 "Minimum triangulation angle in degrees (__auto__ source selection).");
  MSP_ADD_IGNORED_OPTION(t, *p, incident_angle_sigma,
                         "Spread of the incident-angle likelihood of COLMAP's view selection; "
                         "view selection follows ACMM.");
  MSP_ADD_IGNORED_OPTION(t, *p, num_iterations,
                         "Number of coordinate-descent iterations; the red-black iterations per "
                         "pass are " +
                             MSP_OPTION_FLAG_OF(MspStereoOptions, advanced_iterations) + " and " +
                             MSP_OPTION_FLAG_OF(MspStereoOptions, advanced_finest_iterations) +
                             " (a COLMAP project.ini lists num_iterations=5).");
  MSP_ADD_OPTION(t, *p, geom_consistency,
                 "Geometric consistency against the source views' maps: every round runs " +
                     MSP_OPTION_FLAG_OF(MspStereoOptions, advanced_geometric_passes) +
                     " geometric passes after its photometric one; writes the filtered "
                     "*.geometric.bin besides the unfiltered *.photometric.bin, as COLMAP. false = "
                     "the photometric pass alone, filtered into *.photometric.bin.");
  MSP_ADD_OPTION(t, *p, geom_consistency_regularizer,
                 "Weight of the geometric consistency term in pixels (the reprojection error, "
                 "with --MspStereo.geom_consistency_depth_error 0) relative to the photometric "
                 "cost; the term in depth takes --MspStereo.geom_consistency_depth_weight.");
  MSP_ADD_OPTION(
      t, *p, geom_consistency_max_cost,
      "Maximum geometric consistency cost in pixels (forward-backward reprojection error).");
  MSP_ADD_OPTION(t, *p, filter,
                 "Filter the final depth and normal maps: a pixel is kept when at least "
                 "filter_min_num_consistent of its source views are consistent, each on its own: "
                 "NCC >= filter_min_ncc, triangulation angle >= filter_min_triangulation_angle "
                 "and, in geometric passes, reprojection error <= "
                 "filter_geom_consistency_max_cost.");
  MSP_ADD_OPTION(t, *p, filter_min_ncc,
                 "Minimum NCC (1 - cost) of a source view to count as consistent in the filter.");
  MSP_ADD_OPTION(t, *p, filter_min_triangulation_angle,
                 "Minimum triangulation angle in degrees of a source view to count as consistent "
                 "in the filter.");
  MSP_ADD_OPTION(t, *p, filter_min_num_consistent,
                 "Minimum number of consistent source views of a pixel to be kept by the filter.");
  MSP_ADD_OPTION(t, *p, filter_geom_consistency_max_cost,
                 "Maximum forward-backward reprojection error in pixels for a source view to "
                 "count as consistent in the filter.");
  MSP_ADD_OPTION(t, *p, cache_size,
                 "Memory budget in gigabytes for what is kept between image-passes: half for "
                 "per-image state (spilled to stereo/msp beyond it), a quarter for images (read "
                 "again beyond it), a quarter for the prior's label layers (README, Memory).");
  MSP_ADD_OPTION(t, *p, allow_missing_files,
                 "Skip missing images or maps of a problem (with a warning) instead of failing.");
  MSP_ADD_IGNORED_OPTION(t, *p, write_consistency_graph,
                         "Write the consistency graphs of the geometric pass; none are written "
                         "(no COLMAP command reads them).");
  MSP_ADD_OPTION(t, *p, num_threads,
                 "Worker threads of the cpu back-end and of the cuda back-end's CPU steps; <= 0 = "
                 "all cores (COLMAP >= 3.10's option). The maps do not depend on it.");
}

// The options a user sets. The ablation switches of the deformable step name
// the row of the paper's Table 3 they remove ("w/o Eqd." ...).
void DefineMspStereoCommonOptions(MspStereoOptions* m, OptionVisitor* t) {
  MSP_ADD_OPTION(t, *m, backend,
                 "{auto, cpu, cuda}. auto: cuda when this build has the CUDA back-end, a CUDA "
                 "device is present and it passes its start-up self-check, else cpu; the log's "
                 "Back-end: line says which and why. cuda without them is an error, before "
                 "anything is written (README, CUDA back-end).");
  MSP_ADD_OPTION(t, *m, shard,
                 "K/N (0 <= K < N): compute the reference images of problems K, K+N, ... as one "
                 "of N processes sharing the workspace (e.g. a Slurm job array): each pass's "
                 "states go to stereo/msp_shared and the next pass starts when every image has "
                 "finished it (docs/cluster.md). \"\" = every image in this process. Maps equal a "
                 "one-process run's.");
  MSP_ADD_OPTION(t, *m, image_list,
                 "File of reference image names (as in images/, one per line, # comments) that "
                 "this process computes, sharing the passes as with " +
                     MSP_OPTION_FLAG(*m, shard) +
                     "; a name that is no problem's reference image stops, naming the file and "
                     "line. \"\" = none. Not with " +
                     MSP_OPTION_FLAG(*m, shard) + ".");
  MSP_ADD_OPTION(t, *m, shard_timeout,
                 "(0, inf). Seconds a shard waits at a pass barrier for the other processes' "
                 "images before it stops, naming them and their shards.");
  MSP_ADD_OPTION(t, *m, mask_path,
                 "Folder of per-image segmentation mask layers <image_name>.<level>.png (16-bit "
                 "labels, docs/segmentation_masks.md); \"\" = <workspace>/masks. Images without "
                 "files use the embedded segmenter, and the log names them.");
  MSP_ADD_OPTION(t, *m, black_level,
                 "Pixels whose whole matching window is darker than this share of full scale "
                 "(a black backdrop, the night sky) have nothing to match: they get no depth and "
                 "cost no time (docs/method.md section 1.6); 0 = match every pixel.");
  MSP_ADD_OPTION(t, *m, window_step,
                 "{1, 2}. Sampling step inside the matching window (2 = the paper's every other "
                 "row and column); replaces " +
                     MSP_OPTION_FLAG_OF(PatchMatchStereoOptions, window_step) + ".");
  MSP_ADD_OPTION(t, *m, bilateral_ncc,
                 "Weight the NCC window bilaterally (COLMAP's sigma_spatial / sigma_color) "
                 "instead of uniformly (APD-MVS).");
  MSP_ADD_OPTION(t, *m, deformable,
                 "Deformable patch matching (APD-MVS) for unreliable pixels, which match over "
                 "reliable anchors, and with it every part MSP-MVS adds (the options below up to " +
                     MSP_OPTION_FLAG(*m, synergistic_optimization) +
                     "); off until it pays on the benchmarks (docs/method.md section 9). false = "
                     "the conventional PatchMatch core alone.");
  MSP_ADD_OPTION(
      t, *m, segment_planes,
      "After each pass, fit a plane to the matched edge pixels on and around each colour "
      "segment (RANSAC) and offer it to the segment's pixels: textureless pixels take "
      "it unless the views reject it, textured ones only when it matches better "
      "(docs/method.md section 2.10).");
  MSP_ADD_OPTION(t, *m, segment_plane_confirmation,
                 "In geometric passes, offer a segment's plane only when the other views' depth "
                 "maps confirm it (reprojection within 1 px) on at least half as many of the "
                 "segment's pixels as the planes they hold.");
  MSP_ADD_OPTION(t, *m, segment_plane_own_support,
                 "A segment's plane counts only its own support: not the border pixels where a "
                 "neighbour with the same plane ends (a window's outline against the sky, a "
                 "roofline); false = every inlier counts.");
  MSP_ADD_OPTION(t, *m, open_sky,
                 "Leave empty the mostly untextured segments open to the image border that have "
                 "no evidence of a depth of their own: no matched edges but the contours of "
                 "textured surfaces, or only their surroundings' plane (the sky, whatever its "
                 "colour; docs/method.md section 2.11); needs segment_planes.");
  MSP_ADD_OPTION(t, *m, normals_from_depth,
                 "Write each pixel's normal as the plane fitted to the 3D points of the pixels "
                 "around it on the same surface, instead of its plane's normal, which scatters on "
                 "weak texture (COLMAP's fusion joins only normals within 10 degrees; "
                 "docs/method.md section 2.9).");
  MSP_ADD_OPTION(t, *m, planar_prior,
                 "In geometric passes, triangulate the pixels whose depth the other views bring "
                 "back, keep the triangles inside one colour segment, and offer each triangle's "
                 "plane to the unconfirmed pixels within it (a planar prior after ACMP; "
                 "docs/method.md section 2.12).");
  MSP_ADD_OPTION(
      t, *m, consensus_planes,
      "In geometric passes, fit planes to each colour segment's pixels that the other "
      "views confirm, and offer the nearest to each weakly textured pixel of the segment "
      "whose depth lies within 3 % of one: thousands of confirmed depths averaged into "
      "one surface (docs/method.md section 2.13).");
  MSP_ADD_OPTION(t, *m, region_windows,
                 "Mask files given (and " + MSP_OPTION_FLAG(*m, segmentation_prior) +
                     "), every matching window keeps only the samples in its centre's region of "
                     "the coarsest mask layer (objects), or unlabelled: a window reaching across "
                     "an object's outline into what lies before or behind it is no evidence for "
                     "its centre (docs/method.md section 2.3). No effect without mask files.");
  MSP_ADD_OPTION(t, *m, depth_range_from_sources,
                 "Depth range of each reference image (unless --PatchMatchStereo.depth_min/max "
                 "are given) from the sparse points it or any of its sources observes in front of "
                 "it and inside its image, for frames with few tracks of their own (real RGB-D or "
                 "video frames; docs/method.md section 2.1); false = its own observations only, as "
                 "COLMAP.");
  MSP_ADD_OPTION(
      t, *m, filter_textureless_by_geometry,
      "With geometric consistency, the final filter counts a weakly textured pixel's "
      "sources by triangulation angle and depth agreement alone: its NCC is noise. false "
      "= the NCC test for every pixel, as COLMAP.");
  MSP_ADD_OPTION(t, *m, filter_max_depth_error,
                 "With geometric consistency, the final filter counts a source when the depth its "
                 "map holds where the pixel's point projects is within this share of the point's "
                 "depth there (the depth error the agreement bounds, as COLMAP's fusion judges "
                 "it; docs/method.md section 2.9). 0 = COLMAP's test: the reprojection error "
                 "in pixels against filter_geom_consistency_max_cost.");
  MSP_ADD_OPTION(t, *m, filter_single_view_depth_error,
                 "With geometric consistency, the final filter also keeps a pixel that a single "
                 "source confirms (every test passed) with the depth within this share, tighter "
                 "than filter_max_depth_error: a floor or wall one other frame sees well "
                 "(docs/method.md section 2.9). 0 = at least filter_min_num_consistent sources, "
                 "as COLMAP.");
  MSP_ADD_OPTION(t, *m, geom_consistency_depth_error,
                 "Geometric passes measure a source's disagreement with a pixel's point in depth "
                 "instead of reprojected pixels: this share of the depth costs what one pixel "
                 "does (docs/method.md section 2.7). 0 = COLMAP's reprojection error in pixels.");
  MSP_ADD_OPTION(t, *m, geom_consistency_depth_weight,
                 "Weight of the geometric term in depth (geom_consistency_depth_error > 0) "
                 "relative to the photometric cost; replaces "
                 "--PatchMatchStereo.geom_consistency_regularizer, which weighs the term in "
                 "pixels (geom_consistency_depth_error 0).");
  MSP_ADD_OPTION(t, *m, equidistribution,
                 "Adaptive equidistribution (eq. 7): where a depth edge or the border closes one "
                 "of an unreliable pixel's 8 anchor sectors, re-cut the sectors so that each "
                 "faces about as many reliable pixels; false = fixed 45-degree sectors (w/o "
                 "Eqd.).");
  MSP_ADD_OPTION(t, *m, segmentation_prior,
                 "Confine anchors by the multi-granularity segmentation prior (mask layers from " +
                     MSP_OPTION_FLAG(*m, mask_path) +
                     ", else the embedded segmenter): after each deformable pass its depth edges "
                     "are recomputed, and later passes take no anchor across them; needs " +
                     MSP_OPTION_FLAG(*m, deformable) +
                     ". Mask files given, their finest layer also bounds the segment planes and "
                     "the consensus planes (docs/method.md sections 2.10, 2.13), with or without "
                     "deformable patches. false = "
                     "w/o Mul. (APD-MVS), and mask files are not read.");
  MSP_ADD_OPTION(t, *m, edge_aggregation,
                 "Aggregate the mask layers per region by their best anchor subsets (eqs. 4-5); "
                 "false = the union of all layers' boundaries (w/o Agr.).");
  MSP_ADD_OPTION(t, *m, edge_refinement,
                 "Refine the aggregated edges with the colour/depth CRF (eq. 6; colour only on an "
                 "image's first call); false = w/o Ref.");
  MSP_ADD_OPTION(t, *m, geometry_layers,
                 "Add a label layer segmented from each image's current depth and normal maps "
                 "to the embedded segmenter's colour layers, so the prior's edges can follow "
                 "depth edges and creases between surfaces of alike colour (mask files get "
                 "none; docs/method.md section 4.1); false = colour layers only.");
  MSP_ADD_OPTION(t, *m, segmenter,
                 "{opencv, embedded}. Felzenszwalb-Huttenlocher graph segmentation of the "
                 "embedded label layers and of segment planes: OpenCV contrib's (ximgproc) or "
                 "this project's own (that of earlier versions: their results bit for bit).");
  MSP_ADD_OPTION(t, *m, write_previews,
                 "Write pictures of each image's final maps to stereo/prior_previews/: "
                 "<image>.depth.png (colour scale, near red, far blue), <image>.normal.png, "
                 "<image>.error.png (with <workspace>/ground_truth: green within 1%, yellow 5%, "
                 "red beyond, grey no depth) and, with the segmentation prior, <image>.png with "
                 "its aggregated (red) and refined (green) edges.");
  MSP_ADD_OPTION(t, *m, disassemble_clustering,
                 "Disassemble-clustering: keep every anchor within the RANSAC threshold (up to "
                 "4 per sector), cluster them with DBSCAN in the image and let each cluster "
                 "(at most 8, the largest) count once in the deformable cost, its k anchors "
                 "with sub-patches of side 11/k px; false = APD's 8 anchor windows (w/o Clu.).");
  MSP_ADD_OPTION(t, *m, synergistic_optimization,
                 "Disparity-sampling synergistic 3D optimization (eqs. 8-9): the deformable "
                 "patch's sampling pixels lie at random in its sub-patches; each unreliable pixel "
                 "draws " +
                     MSP_OPTION_FLAG(*m, advanced_sampling_solutions) +
                     " new solutions, keeps the one whose cost profile over " +
                     MSP_OPTION_FLAG(*m, advanced_disparity_samples) +
                     " disparities minimises eq. 9 and tries that profile's best depth; false = "
                     "the fixed sampling grid (w/o Syn.).");
}

// --MspStereo.advanced_*: the schedule of the coarse-to-fine rounds, then the
// numeric internals of the deformable step.
void DefineMspStereoAdvancedOptions(MspStereoOptions* m, OptionVisitor* t) {
  MSP_ADD_OPTION(t, *m, advanced_coarsest_image_size,
                 "Coarse-to-fine rounds halve the images until the larger side is at most this "
                 "many pixels (4 rounds at 640x480: a window at 80 px sees across a blank wall); "
                 "one round when the images are already that small.");
  MSP_ADD_OPTION(t, *m, advanced_iterations,
                 "Red-black iterations per pass (1..3) in every round but the finest of several; "
                 "replaces --PatchMatchStereo.num_iterations.");
  MSP_ADD_OPTION(t, *m, advanced_finest_iterations,
                 "Red-black iterations per pass in the finest round when there are several "
                 "rounds (1..3): that round restores detail on the coarser rounds' planes.");
  MSP_ADD_OPTION(t, *m, advanced_geometric_passes,
                 "Geometric passes per round after its photometric pass (1..3, with "
                 "--PatchMatchStereo.geom_consistency), in every round but the finest of several.");
  MSP_ADD_OPTION(t, *m, advanced_finest_geometric_passes,
                 "Geometric passes in the finest round when there are several rounds (1..3): the "
                 "coarser rounds made the maps consistent, the finest restores detail.");
  MSP_ADD_OPTION(t, *m, advanced_restoring_image_size,
                 "Rounds after the first whose images' larger side is at least this many pixels "
                 "restore detail as the finest round does: every option that names the finest "
                 "round (--MspStereo.advanced_finest_*, advanced_weighted_views_only) "
                 "applies to them. The planes are found below this size, as in a 640x480 run (at "
                 "1536x1024 the rounds at 768 and 1536 px restore). 0 = the finest round only.");
  MSP_ADD_OPTION(t, *m, advanced_deformable_max_image_size,
                 "Rounds whose images' larger side exceeds this many pixels run the conventional "
                 "sweeps instead of the deformable step (at 640x480 with coarsest_image_size 80: "
                 "the round at 80 px is deformable, 160, 320 and 640 conventional); 0 = no "
                 "limit.");
  MSP_ADD_OPTION(t, *m, advanced_finest_refine_radius,
                 "Disparity pixels each side of the local refinement's sweep in the finest round "
                 "when there are several rounds (1..5; the coarser rounds sweep 5): the planes "
                 "carried up are within a coarse pixel, and where the cost is flat (weak texture) "
                 "a wider sweep lets the noise move the depth.");
  MSP_ADD_OPTION(t, *m, advanced_finest_hold_weak_texture,
                 "With several rounds, the finest round (with conventional sweeps) leaves a "
                 "weakly textured pixel (matching window's standard deviation below 0.02) whose "
                 "neighbours 5 px away lie on its plane within 1 % the plane the coarser rounds "
                 "carried up: no sweep or local refinement moves it (at full size its cost is "
                 "flat noise), while it is scored, propagates and is filtered as any; near a "
                 "depth edge the pixels are swept. false = every pixel is swept.");
  MSP_ADD_OPTION(t, *m, advanced_finest_deformable,
                 "With several rounds, the finest round also runs the deformable step (slow at "
                 "full size); false = conventional sweeps there (the coarser rounds found the "
                 "textureless planes).");
  MSP_ADD_OPTION(t, *m, advanced_weighted_views_only,
                 "With several rounds, the finest round scores propagation candidates only on "
                 "the views the pixel selected last (carried up from the coarser rounds), not on "
                 "every source view; a pixel whose selected views all mismatch falls back to "
                 "every view. false = every source view.");
  MSP_ADD_OPTION(t, *m, advanced_joint_bilateral_upsampling,
                 "Carry each pixel's plane up to the next round from the coarse pixel among the "
                 "3x3 around it that a joint-bilateral vote guided by the image picks (ACMM), so "
                 "depth edges follow image edges; false = the coarse pixel it falls in.");
  MSP_ADD_OPTION(t, *m, advanced_reliable_max_cost,
                 "[0, 2]. A pixel whose lowest disparity-curve minimum costs more is unreliable.");
  MSP_ADD_OPTION(t, *m, advanced_reliable_single_cost,
                 "[0, 2]. A single curve minimum makes the pixel reliable at or below this cost.");
  MSP_ADD_OPTION(
      t, *m, advanced_reliable_min_spread,
      "[0, 2]. With several curve minima, the others must lie this far above the lowest.");
  MSP_ADD_OPTION(t, *m, advanced_anchor_max_distance,
                 "Anchor search range in pixels of the current round (>= 2).");
  MSP_ADD_OPTION(t, *m, advanced_equidistribution_iterations,
                 "[1, 3]. Re-cuts of the sectors per pixel (each casts up to 8 boundary rays).");
  MSP_ADD_OPTION(t, *m, advanced_num_mask_levels,
                 "Label layers of the embedded segmenter (Felzenszwalb graph segmentation at as "
                 "many scales) for images without mask files (1.." +
                     std::to_string(core::kMaxLabelLayers) + "); mask files set their own count.");
  MSP_ADD_OPTION(t, *m, advanced_crf_alpha,
                 "(0, inf). CRF depth bandwidth as a fraction of the depth range (eq. 6 alpha).");
  MSP_ADD_OPTION(
      t, *m, advanced_crf_beta,
      "(0, inf). CRF colour bandwidth on |I_p . I_q - 1| of normalised RGB (eq. 6 beta).");
  MSP_ADD_OPTION(t, *m, advanced_crf_unary_confidence,
                 "(0, 1). Probability the CRF unary gives the aggregated label.");
  MSP_ADD_OPTION(t, *m, advanced_crf_iterations, "Mean-field iterations of the CRF (>= 1).");
  MSP_ADD_OPTION(t, *m, advanced_dbscan_eta,
                 "[0, " + std::to_string(core::kMaxKeptAnchors - 1) +
                     "]. DBSCAN eta: an anchor with at least this many other anchors within " +
                     MSP_OPTION_FLAG(*m, advanced_dbscan_gamma) + " is a core point.");
  MSP_ADD_OPTION(t, *m, advanced_dbscan_gamma,
                 "[0, inf). DBSCAN gamma: neighbourhood radius in pixels of the current round; 0 "
                 "= automatic, max(3, 0.25 x the median distance of the anchors to the pixel).");
  MSP_ADD_OPTION(t, *m, advanced_sampling_solutions,
                 "[1, " + std::to_string(core::kMaxSamplingSolutions) +
                     "]. J: sampling solutions drawn per optimization.");
  MSP_ADD_OPTION(t, *m, advanced_sampling_local_search,
                 "Iterative local search (the paper's): in every iteration the solution in use "
                 "competes with J perturbations of itself, each re-sampling one sub-patch; false = "
                 "J independent draws once per pass that replace it.");
  MSP_ADD_OPTION(t, *m, advanced_disparity_samples,
                 "{1, 3, 5, 7}. mu: disparities of a cost profile (eq. 8).");
  MSP_ADD_OPTION(t, *m, advanced_disparity_step,
                 "(0, inf). delta: step between the profile's disparities in pixels (eq. 8).");
  MSP_ADD_OPTION(t, *m, advanced_variance_weight,
                 "[0, inf). omega: weight of the variance term of eq. 9; 0 = w/o Var.");
  MSP_ADD_OPTION(t, *m, advanced_profile_cost_term,
                 "Eq. 9 with the sum of the profile's costs; false = the variance term alone "
                 "(w/o Cst.).");
}

// Options this program had under another name: each is an error that names
// the option to use now (besides the advanced ones, which OptionTable::Add
// remembers).
void DefineRenamedOptions(OptionTable* t) {
  t->AddRenamed(OptionName(MspStereoOptions::kSection, "seed"),
                MSP_OPTION_NAME_OF(StereoCommandOptions, random_seed));
  t->AddRenamed(OptionName(MspStereoOptions::kSection, "num_threads"),
                MSP_OPTION_NAME_OF(PatchMatchStereoOptions, num_threads));
}

}  // namespace

void VisitPatchMatchStereoOptions(PatchMatchStereoOptions* options, OptionVisitor* visitor) {
  DefinePatchMatchStereoOptions(options, visitor);
}

void VisitMspStereoOptions(MspStereoOptions* options, OptionVisitor* visitor) {
  DefineMspStereoCommonOptions(options, visitor);
  DefineMspStereoAdvancedOptions(options, visitor);
}

void DefineStereoCommandOptions(StereoCommandOptions* o, OptionTable* t) {
  DefineTopLevelOptions(o, t);
  DefinePatchMatchStereoOptions(&o->patch_match, t);
  DefineMspStereoCommonOptions(&o->msp, t);
  DefineMspStereoAdvancedOptions(&o->msp, t);
  DefineRenamedOptions(t);
}

}  // namespace msp
