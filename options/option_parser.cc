#include "options/option_parser.h"

#include <algorithm>
#include <boost/program_options.hpp>
#include <cctype>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

#include "core/deformable/deformable_limits.h"
#include "core/deformable/synergistic_optimization.h"
#include "core/prior/prior_limits.h"
#include "options/command_line_common.h"
#include "options/option_name.h"

namespace msp {
namespace {

namespace po = boost::program_options;

using command_line::DefaultText;
using command_line::ValueText;

// `text` as one POSIX shell word: as is when it needs no quoting, else in
// single quotes ('' for the empty string).
std::string ShellWord(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char ch) {
    return std::isalnum(ch) || std::strchr("-_./,:=+@%", ch) != nullptr;
  });
  if (plain) return text;
  std::string quoted = "'";
  for (char ch : text) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

// Collects option definitions into a boost description (used for the command
// line, the ini file and the usage text alike) and remembers how to print each
// field's value.
class OptionTable : public OptionVisitor {
 public:
  explicit OptionTable(po::options_description* description) : description_(description) {}

  void Visit(const std::string& name, int* field, const std::string& help) override {
    Add(name, field, help);
  }
  void Visit(const std::string& name, double* field, const std::string& help) override {
    Add(name, field, help);
  }
  void Visit(const std::string& name, bool* field, const std::string& help) override {
    Add(name, field, help);
  }
  void Visit(const std::string& name, std::string* field, const std::string& help) override {
    Add(name, field, help);
  }

  template <typename T>
  void Add(const std::string& name, T* field, const std::string& help) {
    description_->add_options()(name.c_str(),
                                po::value<T>(field)->default_value(*field, DefaultText(*field)),
                                help.c_str());
    Remember(name, field);
  }

  // An option without a default (e.g. a required path).
  void AddNoDefault(const std::string& name, std::string* field, const std::string& help) {
    description_->add_options()(name.c_str(), po::value<std::string>(field), help.c_str());
    Remember(name, field);
  }

  const std::vector<std::string>& names() const { return names_; }
  // The current value of the index-th option's field, as ValueText gives it.
  std::string Value(size_t index) const { return values_[index](); }

 private:
  template <typename T>
  void Remember(const std::string& name, const T* field) {
    names_.push_back(name);
    values_.emplace_back([field] { return ValueText(*field); });
  }

  po::options_description* description_;
  std::vector<std::string> names_;
  std::vector<std::function<std::string()>> values_;
};

// Registers `options.field` under the name its field gives it (option_name.h),
// so no option name is typed here.
#define MSP_ADD_OPTION(table, options, field, help) \
  (table)->Visit(MSP_OPTION_NAME(options, field), &(options).field, help)
#define MSP_ADD_OPTION_NO_DEFAULT(table, options, field, help) \
  (table)->AddNoDefault(MSP_OPTION_NAME(options, field), &(options).field, help)

// The options of each struct, in usage order. Help texts of the
// PatchMatchStereo options follow the field comments of COLMAP's
// PatchMatchOptions; a help text that points at another option spells it from
// its field too (MSP_OPTION_FLAG).
void DefineTopLevelOptions(StereoCommandOptions* o, OptionTable* t) {
  MSP_ADD_OPTION_NO_DEFAULT(t, *o, workspace_path,
                            "Dense workspace written by `colmap image_undistorter` (required).");
  MSP_ADD_OPTION(t, *o, workspace_format,
                 "{COLMAP, PMVS}. Only COLMAP workspaces can be processed.");
  MSP_ADD_OPTION(t, *o, pmvs_option_name,
                 "Option file name of a PMVS workspace; accepted, ignored (PMVS workspaces are "
                 "refused).");
  MSP_ADD_OPTION(t, *o, config_path,
                 "Problem file to use instead of <workspace>/stereo/patch-match.cfg.");
  MSP_ADD_OPTION_NO_DEFAULT(
      t, *o, project_path,
      "Ini file with [PatchMatchStereo] and [MspStereo] sections; options given on the command "
      "line override it.");
  MSP_ADD_OPTION(
      t, *o, random_seed,
      "COLMAP's global seed; used as " + MSP_OPTION_FLAG(o->msp, seed) + " unless that is given.");
  MSP_ADD_OPTION(t, *o, log_to_stderr, "Accepted for compatibility with COLMAP; ignored.");
  MSP_ADD_OPTION(t, *o, log_level,
                 "Verbosity, as COLMAP's (glog's -v): 2 = every line, 1 = no per-step figures "
                 "(one line per image and pass with the running total and ETA), 0 = no "
                 "per-image lines either (the start, warnings, errors and the final summary).");
}

void DefinePatchMatchStereoOptions(PatchMatchStereoOptions* p, OptionVisitor* t) {
  const std::string bilateral_ncc = MSP_OPTION_FLAG_OF(MspStereoOptions, bilateral_ncc);
  MSP_ADD_OPTION(t, *p, max_image_size,
                 "Maximum image size in either dimension; larger images, their intrinsics and the "
                 "output maps are downsized. -1 = full size.");
  MSP_ADD_OPTION(t, *p, gpu_index,
                 "CUDA device indices separated by commas, e.g. \"0,1\"; -1 = all devices. One "
                 "worker per listed GPU, the images spread over them; read by the cuda back-end "
                 "only (see " +
                     MSP_OPTION_FLAG_OF(MspStereoOptions, backend) + ").");
  MSP_ADD_OPTION(t, *p, depth_min,
                 "Minimum depth of the random search; -1 = from the sparse points of each image.");
  MSP_ADD_OPTION(t, *p, depth_max,
                 "Maximum depth of the random search; -1 = from the sparse points of each image.");
  MSP_ADD_OPTION(t, *p, window_radius,
                 "Half window size of the photo-consistency (NCC) window, at most " +
                     std::to_string(kMaxWindowRadius) + ".");
  MSP_ADD_OPTION(t, *p, window_step,
                 "Step between the pixels sampled inside the window (1 or 2). Accepted, ignored: "
                 "the step is " +
                     MSP_OPTION_FLAG_OF(MspStereoOptions, window_step) + ".");
  MSP_ADD_OPTION(t, *p, sigma_spatial,
                 "Spatial sigma of the bilateral NCC weights; <= 0 = window_radius. Used with " +
                     bilateral_ncc + " true.");
  MSP_ADD_OPTION(
      t, *p, sigma_color,
      "Colour sigma of the bilateral NCC weights. Used with " + bilateral_ncc + " true.");
  MSP_ADD_OPTION(t, *p, num_samples,
                 "Number of source views sampled per pixel to compute the matching cost.");
  MSP_ADD_OPTION(t, *p, ncc_sigma,
                 "Spread of the NCC likelihood used in the view-selection probabilities. "
                 "Accepted, ignored: view selection follows ACMM.");
  MSP_ADD_OPTION(t, *p, min_triangulation_angle,
                 "Minimum triangulation angle in degrees (__auto__ source selection).");
  MSP_ADD_OPTION(t, *p, incident_angle_sigma,
                 "Spread of the incident-angle likelihood used in the view-selection "
                 "probabilities. Accepted, ignored: view selection follows ACMM.");
  MSP_ADD_OPTION(t, *p, num_iterations,
                 "Number of coordinate-descent iterations. Accepted, ignored: every pass runs 3 "
                 "red-black iterations.");
  MSP_ADD_OPTION(t, *p, geom_consistency,
                 "Geometric consistency against the source views' maps: every round runs 3 "
                 "geometric passes after its photometric one; writes the filtered "
                 "*.geometric.bin besides the unfiltered *.photometric.bin. false = the "
                 "photometric pass alone, filtered into *.photometric.bin.");
  MSP_ADD_OPTION(t, *p, geom_consistency_regularizer,
                 "Weight of the geometric consistency term relative to the photometric cost.");
  MSP_ADD_OPTION(
      t, *p, geom_consistency_max_cost,
      "Maximum geometric consistency cost in pixels (forward-backward reprojection error).");
  MSP_ADD_OPTION(t, *p, filter, "Filter the final depth and normal maps.");
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
                 "Skip missing images or maps of a problem instead of failing.");
  MSP_ADD_OPTION(t, *p, write_consistency_graph,
                 "Write the consistency graphs of the geometric pass. Accepted, ignored: none are "
                 "written (no COLMAP command reads them).");
  MSP_ADD_OPTION(t, *p, num_threads,
                 "COLMAP >= 3.10 I/O thread count; accepted for compatibility and ignored (see " +
                     MSP_OPTION_FLAG_OF(MspStereoOptions, num_threads) + ").");
}

void DefineMspStereoOptions(MspStereoOptions* m, OptionVisitor* t) {
  MSP_ADD_OPTION(t, *m, backend,
                 "{auto, cpu, cuda}. auto: cuda when this build has the CUDA back-end and a CUDA "
                 "device is present, else cpu (the log says which). cuda without either is an "
                 "error.");
  MSP_ADD_OPTION(
      t, *m, seed,
      "Seed of the counter-based random numbers (>= 0); a run is a pure function of it.");
  MSP_ADD_OPTION(t, *m, num_threads, "Worker threads of the cpu back-end; <= 0 = all cores.");
  MSP_ADD_OPTION(t, *m, shard,
                 "K/N (0 <= K < N): compute the reference images of problems K, K+N, ... as one "
                 "of N processes sharing the workspace (e.g. a Slurm job array): each pass's "
                 "states go to stereo/msp_shared and the next pass starts when every image has "
                 "finished it. \"\" = every image in this process. Maps equal a one-process "
                 "run's.");
  MSP_ADD_OPTION(t, *m, image_list,
                 "File of reference image names (as in images/, one per line, # comments) that "
                 "this process computes, sharing the passes as with " +
                     MSP_OPTION_FLAG(*m, shard) + "; \"\" = none. Not with " +
                     MSP_OPTION_FLAG(*m, shard) + ".");
  MSP_ADD_OPTION(t, *m, shard_timeout,
                 "(0, inf). Seconds a shard waits at a pass barrier for the other processes' "
                 "images before it stops, naming them.");
  MSP_ADD_OPTION(t, *m, mask_path,
                 "Folder of per-image segmentation mask layers; \"\" = <workspace>/masks.");
  MSP_ADD_OPTION(t, *m, coarsest_image_size,
                 "Coarse-to-fine rounds halve the images until the larger side is at most this "
                 "many pixels; one round when the images are already that small.");
  MSP_ADD_OPTION(t, *m, iterations,
                 "Red-black iterations per pass (1..3) in every round but the finest of several; "
                 "replaces --PatchMatchStereo.num_iterations.");
  MSP_ADD_OPTION(t, *m, finest_iterations,
                 "Red-black iterations per pass in the finest round when there are several "
                 "rounds (1..3): that round restores detail on the coarser rounds' planes.");
  MSP_ADD_OPTION(t, *m, geometric_passes,
                 "Geometric passes per round after its photometric pass (1..3, with "
                 "--PatchMatchStereo.geom_consistency), in every round but the finest of several.");
  MSP_ADD_OPTION(t, *m, finest_geometric_passes,
                 "Geometric passes in the finest round when there are several rounds (1..3): the "
                 "coarser rounds made the maps consistent, the finest restores detail.");
  MSP_ADD_OPTION(t, *m, deformable_max_image_size,
                 "Rounds whose images' larger side exceeds this many pixels run the conventional "
                 "sweeps instead of the deformable step; 0 = no limit.");
  MSP_ADD_OPTION(t, *m, black_level,
                 "Pixels whose whole matching window is darker than this share of full scale "
                 "(a black backdrop, the night sky) have nothing to match: they get no depth and "
                 "cost no time; 0 = match every pixel.");
  MSP_ADD_OPTION(t, *m, finest_refine_radius,
                 "Disparity pixels each side of the local refinement's sweep in the finest round "
                 "when there are several rounds (1..5; the coarser rounds sweep 5): the planes "
                 "carried up are within a coarse pixel.");
  MSP_ADD_OPTION(t, *m, finest_deformable,
                 "With several rounds, the finest round also runs the deformable step; false = "
                 "conventional sweeps there (the coarser rounds found the textureless planes).");
  MSP_ADD_OPTION(t, *m, weighted_views_only,
                 "With several rounds, the finest round scores propagation candidates only on "
                 "the views the pixel selected last (carried up from the coarser rounds), not on "
                 "every source view; false = every source view.");
  MSP_ADD_OPTION(t, *m, joint_bilateral_upsampling,
                 "Carry each pixel's plane up to the next round from the coarse pixel among the "
                 "3x3 around it that a joint-bilateral vote guided by the image picks (ACMM), so "
                 "depth edges follow image edges; false = the coarse pixel it falls in.");
  MSP_ADD_OPTION(t, *m, window_step,
                 "{1, 2}. Sampling step inside the matching window (2 = the paper's every other "
                 "row and column); replaces " +
                     MSP_OPTION_FLAG_OF(PatchMatchStereoOptions, window_step) + ".");
  MSP_ADD_OPTION(t, *m, bilateral_ncc,
                 "Weight the NCC window bilaterally (COLMAP's sigma_spatial / sigma_color) "
                 "instead of uniformly (APD-MVS).");
  MSP_ADD_OPTION(t, *m, deformable,
                 "Deformable patch matching (APD-MVS): unreliable pixels match over reliable "
                 "anchors; false = the conventional PatchMatch core alone.");
  MSP_ADD_OPTION(
      t, *m, segment_planes,
      "After each pass, fit a plane to the matched edge pixels on and around each colour "
      "segment (RANSAC) and offer it to the segment's pixels: textureless pixels take "
      "it unless the views reject it, textured ones only when it matches better.");
  MSP_ADD_OPTION(t, *m, segment_plane_confirmation,
                 "In geometric passes, offer a segment's plane only when the other views' depth "
                 "maps confirm it (reprojection within 1 px) on at least half as many of the "
                 "segment's pixels as the planes they hold.");
  MSP_ADD_OPTION(t, *m, segment_plane_own_support,
                 "A segment's plane counts only its own support: not the border pixels where a "
                 "neighbour with the same plane ends (a window's outline against the sky, a "
                 "roofline); false = every inlier counts.");
  MSP_ADD_OPTION(t, *m, open_sky,
                 "Leave empty the sky-coloured (bright and blue, or white-out), mostly untextured "
                 "segments that touch the image border and have no plane of their own (the sky); "
                 "needs segment_planes.");
  MSP_ADD_OPTION(t, *m, depth_range_from_sources,
                 "Depth range of each reference image (unless --PatchMatchStereo.depth_min/max "
                 "are given) from the sparse points it or any of its sources observes in front of "
                 "it and inside its image; false = its own observations only, as COLMAP.");
  MSP_ADD_OPTION(t, *m, filter_textureless_by_geometry,
                 "With geometric consistency, the final filter counts a weakly textured pixel's "
                 "sources by triangulation angle and reprojection alone: its NCC is noise. false "
                 "= the NCC test for every pixel, as COLMAP.");
  MSP_ADD_OPTION(t, *m, reliable_max_cost,
                 "[0, 2]. A pixel whose lowest disparity-curve minimum costs more is unreliable.");
  MSP_ADD_OPTION(t, *m, reliable_single_cost,
                 "[0, 2]. A single curve minimum makes the pixel reliable at or below this cost.");
  MSP_ADD_OPTION(
      t, *m, reliable_min_spread,
      "[0, 2]. With several curve minima, the others must lie this far above the lowest.");
  MSP_ADD_OPTION(t, *m, anchor_max_distance,
                 "Anchor search range in pixels of the current round (>= 2).");
  MSP_ADD_OPTION(t, *m, equidistribution,
                 "Adaptive equidistribution (eq. 7): re-cut each unreliable pixel's 8 anchor "
                 "sectors so that each faces about as many reliable pixels, recovering anchors in "
                 "sectors walled off by depth edges; false = fixed 45-degree sectors (w/o Eqd.).");
  MSP_ADD_OPTION(t, *m, equidistribution_iterations,
                 "[1, 3]. Re-cuts of the sectors per pixel (each casts up to 8 boundary rays).");
  MSP_ADD_OPTION(t, *m, segmentation_prior,
                 "Confine anchors by the multi-granularity segmentation prior (mask layers from " +
                     MSP_OPTION_FLAG(*m, mask_path) +
                     ", else the embedded segmenter): after each deformable pass its depth edges "
                     "are recomputed, and later passes take no anchor across them; needs " +
                     MSP_OPTION_FLAG(*m, deformable) + ". false = w/o Mul. (APD-MVS).");
  MSP_ADD_OPTION(t, *m, edge_aggregation,
                 "Aggregate the mask layers per region by their best anchor subsets (eqs. 4-5); "
                 "false = the union of all layers' boundaries (w/o Agr.).");
  MSP_ADD_OPTION(t, *m, edge_refinement,
                 "Refine the aggregated edges with the colour/depth CRF (eq. 6); false = w/o Ref.");
  MSP_ADD_OPTION(t, *m, num_mask_levels,
                 "Label layers of the embedded segmenter for images without mask files (1.." +
                     std::to_string(core::kMaxLabelLayers) + "); mask files set their own count.");
  MSP_ADD_OPTION(t, *m, geometry_layers,
                 "Add a label layer segmented from each image's current depth and normal maps "
                 "to the embedded segmenter's colour layers, so the prior's edges can follow "
                 "depth edges and creases between surfaces of alike colour (mask files get "
                 "none); false = colour layers only.");
  MSP_ADD_OPTION(t, *m, segmenter,
                 "{opencv, embedded}. Felzenszwalb-Huttenlocher graph segmentation of the "
                 "embedded label layers and of segment planes: OpenCV contrib's (ximgproc) or "
                 "this project's own.");
  MSP_ADD_OPTION(t, *m, write_previews,
                 "Write pictures of each image's final maps to stereo/prior_previews/: "
                 "<image>.depth.png (colour scale, near red, far blue), <image>.normal.png, "
                 "<image>.error.png (with <workspace>/ground_truth: green within 1%, yellow 5%, "
                 "red beyond, grey no depth) and, with the segmentation prior, <image>.png with "
                 "its aggregated (red) and refined (green) edges.");
  MSP_ADD_OPTION(t, *m, crf_alpha,
                 "(0, inf). CRF depth bandwidth as a fraction of the depth range (eq. 6 alpha).");
  MSP_ADD_OPTION(
      t, *m, crf_beta,
      "(0, inf). CRF colour bandwidth on |I_p . I_q - 1| of normalised RGB (eq. 6 beta).");
  MSP_ADD_OPTION(t, *m, crf_unary_confidence,
                 "(0, 1). Probability the CRF unary gives the aggregated label.");
  MSP_ADD_OPTION(t, *m, crf_iterations, "Mean-field iterations of the CRF (>= 1).");
  MSP_ADD_OPTION(t, *m, disassemble_clustering,
                 "Disassemble-clustering: keep every anchor within the RANSAC threshold (up to "
                 "4 per sector), cluster them with DBSCAN in the image and let each cluster "
                 "(at most 8, the largest) count once in the deformable cost, its k anchors "
                 "with sub-patches of side 11/k px; false = APD's 8 anchor windows (w/o Clu.).");
  MSP_ADD_OPTION(t, *m, dbscan_eta,
                 "[0, " + std::to_string(core::kMaxKeptAnchors - 1) +
                     "]. DBSCAN eta: an anchor with at least this many other anchors within " +
                     MSP_OPTION_FLAG(*m, dbscan_gamma) + " is a core point.");
  MSP_ADD_OPTION(t, *m, dbscan_gamma,
                 "[0, inf). DBSCAN gamma: neighbourhood radius in pixels of the current round; 0 "
                 "= automatic, max(3, 0.25 x the median distance of the anchors to the pixel).");
  MSP_ADD_OPTION(t, *m, synergistic_optimization,
                 "Disparity-sampling synergistic 3D optimization (eqs. 8-9): the deformable "
                 "patch's sampling pixels lie at random in its sub-patches; once per deformable "
                 "pass each pixel draws " +
                     MSP_OPTION_FLAG(*m, sampling_solutions) +
                     " new solutions, keeps the one whose cost profile over " +
                     MSP_OPTION_FLAG(*m, disparity_samples) +
                     " disparities minimises eq. 9 and tries that profile's best depth; false = "
                     "the fixed sampling grid (w/o Syn.).");
  MSP_ADD_OPTION(t, *m, sampling_solutions,
                 "[1, " + std::to_string(core::kMaxSamplingSolutions) +
                     "]. J: sampling solutions drawn per optimization.");
  MSP_ADD_OPTION(t, *m, sampling_local_search,
                 "Iterative local search (the paper's): in every iteration the solution in use "
                 "competes with J perturbations of itself, each re-sampling one sub-patch; false = "
                 "J independent draws once per pass that replace it.");
  MSP_ADD_OPTION(t, *m, disparity_samples,
                 "{1, 3, 5, 7}. mu: disparities of a cost profile (eq. 8).");
  MSP_ADD_OPTION(t, *m, disparity_step,
                 "(0, inf). delta: step between the profile's disparities in pixels (eq. 8).");
  MSP_ADD_OPTION(t, *m, variance_weight,
                 "[0, inf). omega: weight of the variance term of eq. 9; 0 = w/o Var.");
  MSP_ADD_OPTION(t, *m, profile_cost_term,
                 "Eq. 9 with the sum of the profile's costs; false = the variance term alone "
                 "(w/o Cst.).");
}

// The one list of options: the top-level ones, then each section's.
void DefineOptions(StereoCommandOptions* o, OptionTable* t) {
  DefineTopLevelOptions(o, t);
  DefinePatchMatchStereoOptions(&o->patch_match, t);
  DefineMspStereoOptions(&o->msp, t);
}

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// Reads the ini file into `vm`. Values already in `vm` (from the command line)
// win, because boost's store() never overwrites a stored value.
void StoreIniFile(const std::string& path, const po::options_description& description,
                  po::variables_map* vm) {
  const std::string in_file =
      MSP_OPTION_FLAG_OF(StereoCommandOptions, project_path) + " file `" + path + "`";
  std::ifstream file(path);
  if (!file) throw OptionError("cannot open " + in_file);
  po::parsed_options parsed(&description);
  try {
    parsed = po::parse_config_file(file, description, /*allow_unregistered=*/true);
  } catch (const po::error& e) {
    throw OptionError("in " + in_file + ": " + e.what());
  }
  std::vector<po::option> known;
  for (const po::option& option : parsed.options) {
    if (!option.unregistered) {
      known.push_back(option);
      continue;
    }
    // Keys of other COLMAP commands are expected in a project.ini; a key in
    // one of our sections that we do not know is a typo.
    if (StartsWith(option.string_key, std::string(PatchMatchStereoOptions::kSection) + ".") ||
        StartsWith(option.string_key, std::string(MspStereoOptions::kSection) + ".")) {
      throw OptionError("unknown option `" + option.string_key + "` in " + in_file);
    }
  }
  parsed.options = std::move(known);
  try {
    po::store(parsed, *vm);
  } catch (const po::error& e) {
    throw OptionError("in " + in_file + ": " + e.what());
  }
}

std::string ToUpper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  return text;
}

}  // namespace

ParseStatus ParseStereoCommand(int argc, const char* const argv[], StereoCommandOptions* options) {
  if (command_line::HasHelpFlag(argc, argv)) return ParseStatus::kHelp;

  po::options_description description;
  OptionTable table(&description);
  DefineOptions(options, &table);

  // COLMAP commands take no bare words (positional options).
  po::variables_map vm;
  command_line::StoreCommandLine(argc, argv, description, /*positional=*/{}, &vm);
  const std::string project_key = MSP_OPTION_NAME(*options, project_path);
  if (vm.count(project_key) && !vm[project_key].as<std::string>().empty()) {
    StoreIniFile(vm[project_key].as<std::string>(), description, &vm);
  }
  command_line::NotifyOptions(&vm);

  const std::string workspace_key = MSP_OPTION_NAME(*options, workspace_path);
  if (!vm.count(workspace_key) || options->workspace_path.empty()) {
    throw OptionError("missing required option " + MSP_OPTION_FLAG(*options, workspace_path));
  }
  if (vm[MSP_OPTION_NAME(options->msp, seed)].defaulted() &&
      !vm[MSP_OPTION_NAME(*options, random_seed)].defaulted()) {
    options->msp.seed = options->random_seed;
  }
  options->workspace_format = ToUpper(options->workspace_format);
  return ParseStatus::kRun;
}

void VisitPatchMatchStereoOptions(PatchMatchStereoOptions* options, OptionVisitor* visitor) {
  DefinePatchMatchStereoOptions(options, visitor);
}

void VisitMspStereoOptions(MspStereoOptions* options, OptionVisitor* visitor) {
  DefineMspStereoOptions(options, visitor);
}

std::string StereoCommandUsage() {
  StereoCommandOptions options;
  po::options_description description(
      "Usage: msp_stereo --workspace_path <dense workspace> [options]\n"
      "       colmap msp_stereo --workspace_path <dense workspace> [options]\n\n"
      "Dense stereo for a COLMAP workspace; writes stereo/{depth,normal}_maps like\n"
      "`colmap patch_match_stereo`. Options come from the command line or from the\n"
      "[PatchMatchStereo] / [MspStereo] sections of a --project_path ini file; the\n"
      "command line overrides the ini file.\n\nOptions",
      command_line::kHelpLineLength, command_line::kHelpMinDescriptionLength);
  command_line::AddHelpOption(&description);
  OptionTable table(&description);
  DefineOptions(&options, &table);
  std::ostringstream stream;
  stream << description;
  return stream.str();
}

std::vector<std::string> StereoCommandOptionNames() {
  StereoCommandOptions options;
  po::options_description description;
  OptionTable table(&description);
  DefineOptions(&options, &table);
  return table.names();
}

void PrintStereoCommandOptions(const StereoCommandOptions& options, std::ostream& out) {
  // The table binds to fields it may write through; it only reads this copy.
  StereoCommandOptions copy = options;
  po::options_description description;
  OptionTable table(&description);
  DefineOptions(&copy, &table);
  for (size_t i = 0; i < table.names().size(); ++i) {
    out << "--" << table.names()[i] << " " << ShellWord(table.Value(i)) << "\n";
  }
}

}  // namespace msp
