#include "options/option_parser.h"

#include <algorithm>
#include <boost/program_options.hpp>
#include <cctype>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

#include "core/prior/prior_limits.h"

namespace msp {
namespace {

namespace po = boost::program_options;

// Options COLMAP accepts on every command (and one only newer COLMAP has).
// They are parsed so that COLMAP command lines and project files work; only
// random_seed has an effect (it seeds --MspStereo.seed unless that is given).
struct CompatibilityOptions {
  int random_seed = 0;
  bool log_to_stderr = false;
  int log_level = 2;
  int patch_match_num_threads = -1;
};

std::string ToText(const std::string& value) { return value.empty() ? "\"\"" : value; }
std::string ToText(bool value) { return value ? "true" : "false"; }
template <typename T>
std::string ToText(const T& value) {
  std::ostringstream stream;
  stream << value;
  return stream.str();
}

// Collects option definitions into a boost description (used for the command
// line, the ini file and the usage text alike) and remembers how to print each
// field's value.
class OptionTable {
 public:
  explicit OptionTable(po::options_description* description) : description_(description) {}

  template <typename T>
  void Add(const std::string& name, T* field, const std::string& help) {
    description_->add_options()(
        name.c_str(), po::value<T>(field)->default_value(*field, ToText(*field)), help.c_str());
    names_.push_back(name);
    printers_.emplace_back([field] { return ToText(*field); });
    is_field_.push_back(true);
  }

  // An option kept only so COLMAP command lines parse; not in the structs.
  template <typename T>
  void AddCompatibility(const std::string& name, T* value, const std::string& help) {
    Add(name, value, help);
    is_field_.back() = false;
  }

  // An option without a default (e.g. a required path).
  void AddNoDefault(const std::string& name, std::string* field, const std::string& help) {
    description_->add_options()(name.c_str(), po::value<std::string>(field), help.c_str());
    names_.push_back(name);
    printers_.emplace_back([field] { return ToText(*field); });
    is_field_.push_back(true);
  }

  const std::vector<std::string>& names() const { return names_; }
  bool IsField(size_t index) const { return is_field_[index]; }
  std::string Print(size_t index) const { return printers_[index](); }

 private:
  po::options_description* description_;
  std::vector<std::string> names_;
  std::vector<std::function<std::string()>> printers_;
  std::vector<bool> is_field_;
};

constexpr char kPatchMatchSection[] = "PatchMatchStereo";
constexpr char kMspSection[] = "MspStereo";

// The one list of options. Help texts of the PatchMatchStereo options follow
// the field comments of COLMAP's PatchMatchOptions.
void DefineOptions(StereoCommandOptions* o, CompatibilityOptions* c, OptionTable* t) {
  t->AddNoDefault("workspace_path", &o->workspace_path,
                  "Dense workspace written by `colmap image_undistorter` (required).");
  t->Add("workspace_format", &o->workspace_format,
         "{COLMAP, PMVS}. Only COLMAP workspaces can be processed.");
  t->Add("pmvs_option_name", &o->pmvs_option_name, "Option file name of a PMVS workspace.");
  t->Add("config_path", &o->config_path,
         "Problem file to use instead of <workspace>/stereo/patch-match.cfg.");
  t->AddNoDefault("project_path", &o->project_path,
                  "Ini file with [PatchMatchStereo] and [MspStereo] sections; options given on "
                  "the command line override it.");
  t->AddCompatibility("random_seed", &c->random_seed,
                      "COLMAP's global seed; used as --MspStereo.seed unless that is given.");
  t->AddCompatibility("log_to_stderr", &c->log_to_stderr,
                      "Accepted for compatibility with COLMAP; ignored.");
  t->AddCompatibility("log_level", &c->log_level,
                      "Accepted for compatibility with COLMAP; ignored.");

  PatchMatchStereoOptions& p = o->patch_match;
  const std::string pm = std::string(kPatchMatchSection) + ".";
  t->Add(pm + "max_image_size", &p.max_image_size,
         "Maximum image size in either dimension; larger images, their intrinsics and the "
         "output maps are downsized. -1 = full size.");
  t->Add(pm + "gpu_index", &p.gpu_index,
         "CUDA device indices separated by commas, e.g. \"0,1\"; -1 = all devices. Only used by "
         "the cuda back-end.");
  t->Add(pm + "depth_min", &p.depth_min,
         "Minimum depth of the random search; -1 = from the sparse points of each image.");
  t->Add(pm + "depth_max", &p.depth_max,
         "Maximum depth of the random search; -1 = from the sparse points of each image.");
  t->Add(pm + "window_radius", &p.window_radius,
         "Half window size of the photo-consistency (NCC) window, at most " +
             std::to_string(kMaxWindowRadius) + ".");
  t->Add(pm + "window_step", &p.window_step,
         "Step between the pixels sampled inside the window (1 or 2).");
  t->Add(pm + "sigma_spatial", &p.sigma_spatial,
         "Spatial sigma of the bilateral NCC weights; <= 0 = window_radius.");
  t->Add(pm + "sigma_color", &p.sigma_color, "Colour sigma of the bilateral NCC weights.");
  t->Add(pm + "num_samples", &p.num_samples,
         "Number of source views sampled per pixel to compute the matching cost.");
  t->Add(pm + "ncc_sigma", &p.ncc_sigma,
         "Spread of the NCC likelihood used in the view-selection probabilities.");
  t->Add(pm + "min_triangulation_angle", &p.min_triangulation_angle,
         "Minimum triangulation angle in degrees (view selection and __auto__ sources).");
  t->Add(pm + "incident_angle_sigma", &p.incident_angle_sigma,
         "Spread of the incident-angle likelihood used in the view-selection probabilities.");
  t->Add(pm + "num_iterations", &p.num_iterations, "Number of coordinate-descent iterations.");
  t->Add(pm + "geom_consistency", &p.geom_consistency,
         "Add a second pass with geometric consistency against the source views' maps; "
         "writes *.geometric.bin besides the unfiltered *.photometric.bin.");
  t->Add(pm + "geom_consistency_regularizer", &p.geom_consistency_regularizer,
         "Weight of the geometric consistency term relative to the photometric cost.");
  t->Add(pm + "geom_consistency_max_cost", &p.geom_consistency_max_cost,
         "Maximum geometric consistency cost in pixels (forward-backward reprojection error).");
  t->Add(pm + "filter", &p.filter, "Filter the final depth and normal maps.");
  t->Add(pm + "filter_min_ncc", &p.filter_min_ncc,
         "Minimum NCC (1 - cost) of a pixel to be kept by the filter.");
  t->Add(pm + "filter_min_triangulation_angle", &p.filter_min_triangulation_angle,
         "Minimum triangulation angle in degrees of a pixel to be kept by the filter.");
  t->Add(pm + "filter_min_num_consistent", &p.filter_min_num_consistent,
         "Minimum number of consistent source views of a pixel to be kept by the filter.");
  t->Add(pm + "filter_geom_consistency_max_cost", &p.filter_geom_consistency_max_cost,
         "Maximum forward-backward reprojection error in pixels for a source view to count as "
         "consistent in the filter.");
  t->Add(pm + "cache_size", &p.cache_size,
         "Memory budget in gigabytes for cached per-image state.");
  t->Add(pm + "allow_missing_files", &p.allow_missing_files,
         "Skip missing images or maps of a problem instead of failing.");
  t->Add(pm + "write_consistency_graph", &p.write_consistency_graph,
         "Write the consistency graphs of the geometric pass (read by no COLMAP command).");
  t->AddCompatibility(
      pm + "num_threads", &c->patch_match_num_threads,
      "COLMAP >= 3.10 I/O thread count; accepted for compatibility and ignored (see "
      "--MspStereo.num_threads).");

  MspStereoOptions& m = o->msp;
  const std::string ms = std::string(kMspSection) + ".";
  t->Add(ms + "backend", &m.backend,
         "{cpu, cuda}. cuda needs a build with CUDA and a GPU; both give the same maps.");
  t->Add(ms + "seed", &m.seed,
         "Seed of the counter-based random numbers (>= 0); a run is a pure function of it.");
  t->Add(ms + "num_threads", &m.num_threads,
         "Worker threads of the cpu back-end; <= 0 = all cores.");
  t->Add(ms + "mask_path", &m.mask_path,
         "Folder of per-image segmentation mask layers; \"\" = <workspace>/masks.");
  t->Add(ms + "coarsest_image_size", &m.coarsest_image_size,
         "Coarse-to-fine rounds halve the images until the larger side is at most this many "
         "pixels; one round when the images are already that small.");
  t->Add(ms + "window_step", &m.window_step,
         "{1, 2}. Sampling step inside the matching window (2 = the paper's every other row and "
         "column); replaces --PatchMatchStereo.window_step.");
  t->Add(ms + "bilateral_ncc", &m.bilateral_ncc,
         "Weight the NCC window bilaterally (COLMAP's sigma_spatial / sigma_color) instead of "
         "uniformly (APD-MVS).");
  t->Add(ms + "deformable", &m.deformable,
         "Deformable patch matching (APD-MVS): unreliable pixels match over reliable anchors; "
         "false = the conventional PatchMatch core alone.");
  t->Add(ms + "reliable_max_cost", &m.reliable_max_cost,
         "[0, 2]. A pixel whose lowest disparity-curve minimum costs more is unreliable.");
  t->Add(ms + "reliable_single_cost", &m.reliable_single_cost,
         "[0, 2]. A single curve minimum makes the pixel reliable at or below this cost.");
  t->Add(ms + "reliable_min_spread", &m.reliable_min_spread,
         "[0, 2]. With several curve minima, the others must lie this far above the lowest.");
  t->Add(ms + "anchor_max_distance", &m.anchor_max_distance,
         "Anchor search range in pixels of the current round (>= 2).");
  t->Add(ms + "segmentation_prior", &m.segmentation_prior,
         "Confine anchors by the multi-granularity segmentation prior (mask layers from "
         "--MspStereo.mask_path, else the embedded segmenter): after each deformable pass its "
         "depth edges are recomputed, and later passes take no anchor across them; needs "
         "--MspStereo.deformable. false = w/o Mul. (APD-MVS).");
  t->Add(ms + "edge_aggregation", &m.edge_aggregation,
         "Aggregate the mask layers per region by their best anchor subsets (eqs. 4-5); false = "
         "the union of all layers' boundaries (w/o Agr.).");
  t->Add(ms + "edge_refinement", &m.edge_refinement,
         "Refine the aggregated edges with the colour/depth CRF (eq. 6); false = w/o Ref.");
  t->Add(ms + "num_mask_levels", &m.num_mask_levels,
         "Label layers of the embedded segmenter for images without mask files (1.." +
             std::to_string(core::kMaxLabelLayers) + "); mask files set their own count.");
  t->Add(ms + "write_previews", &m.write_previews,
         "Write stereo/prior_previews/<image>.png with the aggregated (red) and refined (green) "
         "edges that confined the final pass, over the image.");
  t->Add(ms + "crf_alpha", &m.crf_alpha,
         "(0, inf). CRF depth bandwidth as a fraction of the depth range (eq. 6 alpha).");
  t->Add(ms + "crf_beta", &m.crf_beta,
         "(0, inf). CRF colour bandwidth on |I_p . I_q - 1| of normalised RGB (eq. 6 beta).");
  t->Add(ms + "crf_unary_confidence", &m.crf_unary_confidence,
         "(0, 1). Probability the CRF unary gives the aggregated label.");
  t->Add(ms + "crf_iterations", &m.crf_iterations, "Mean-field iterations of the CRF (>= 1).");
}

bool IsHelpFlag(const std::string& arg) { return arg == "-h" || arg == "--help"; }

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// Reads the ini file into `vm`. Values already in `vm` (from the command line)
// win, because boost's store() never overwrites a stored value.
void StoreIniFile(const std::string& path, const po::options_description& description,
                  po::variables_map* vm) {
  std::ifstream file(path);
  if (!file) {
    throw OptionError("cannot open --project_path file `" + path + "`");
  }
  po::parsed_options parsed(&description);
  try {
    parsed = po::parse_config_file(file, description, /*allow_unregistered=*/true);
  } catch (const po::error& e) {
    throw OptionError("in --project_path file `" + path + "`: " + e.what());
  }
  std::vector<po::option> known;
  for (const po::option& option : parsed.options) {
    if (!option.unregistered) {
      known.push_back(option);
      continue;
    }
    // Keys of other COLMAP commands are expected in a project.ini; a key in
    // one of our sections that we do not know is a typo.
    if (StartsWith(option.string_key, std::string(kPatchMatchSection) + ".") ||
        StartsWith(option.string_key, std::string(kMspSection) + ".")) {
      throw OptionError("unknown option `" + option.string_key + "` in --project_path file `" +
                        path + "`");
    }
  }
  parsed.options = std::move(known);
  try {
    po::store(parsed, *vm);
  } catch (const po::error& e) {
    throw OptionError("in --project_path file `" + path + "`: " + e.what());
  }
}

std::string ToUpper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  return text;
}

}  // namespace

ParseStatus ParseStereoCommand(int argc, const char* const argv[], StereoCommandOptions* options) {
  // Help wins over everything else, including unknown options next to it.
  for (int i = 1; i < argc; ++i) {
    if (IsHelpFlag(argv[i])) return ParseStatus::kHelp;
  }

  CompatibilityOptions compatibility;
  po::options_description description;
  OptionTable table(&description);
  DefineOptions(options, &compatibility, &table);

  po::variables_map vm;
  try {
    // No prefix guessing: an abbreviated or misspelt name is reported as
    // unknown instead of silently matching some other option.
    const int style = po::command_line_style::unix_style & ~po::command_line_style::allow_guessing;
    const po::parsed_options parsed =
        po::command_line_parser(argc, argv).options(description).style(style).run();
    // boost silently drops bare words; COLMAP commands take none, so a stray
    // word is almost certainly a value whose option name was mistyped.
    for (const po::option& option : parsed.options) {
      if (option.position_key >= 0) {
        throw OptionError("unexpected argument `" + option.original_tokens.front() +
                          "` (options are --name value; run with --help to list them)");
      }
    }
    po::store(parsed, vm);
  } catch (const po::unknown_option& e) {
    throw OptionError("unknown option `" + e.get_option_name() +
                      "` (run with --help to list the options)");
  } catch (const po::error& e) {
    throw OptionError(e.what());
  }

  if (vm.count("project_path") && !vm["project_path"].as<std::string>().empty()) {
    StoreIniFile(vm["project_path"].as<std::string>(), description, &vm);
  }
  try {
    po::notify(vm);
  } catch (const po::error& e) {
    throw OptionError(e.what());
  }

  if (!vm.count("workspace_path") || options->workspace_path.empty()) {
    throw OptionError("missing required option --workspace_path");
  }
  const std::string seed_key = std::string(kMspSection) + ".seed";
  if (vm[seed_key].defaulted() && !vm["random_seed"].defaulted()) {
    options->msp.seed = compatibility.random_seed;
  }
  options->workspace_format = ToUpper(options->workspace_format);
  return ParseStatus::kRun;
}

std::string StereoCommandUsage() {
  StereoCommandOptions options;
  CompatibilityOptions compatibility;
  po::options_description description(
      "Usage: msp_stereo --workspace_path <dense workspace> [options]\n"
      "       colmap msp_stereo --workspace_path <dense workspace> [options]\n\n"
      "Dense stereo for a COLMAP workspace; writes stereo/{depth,normal}_maps like\n"
      "`colmap patch_match_stereo`. Options come from the command line or from the\n"
      "[PatchMatchStereo] / [MspStereo] sections of a --project_path ini file; the\n"
      "command line overrides the ini file.\n\nOptions",
      /*line_length=*/100, /*min_description_length=*/50);
  description.add_options()("help,h", "Print this help and exit.");
  OptionTable table(&description);
  DefineOptions(&options, &compatibility, &table);
  std::ostringstream stream;
  stream << description;
  return stream.str();
}

std::vector<std::string> StereoCommandOptionNames() {
  StereoCommandOptions options;
  CompatibilityOptions compatibility;
  po::options_description description;
  OptionTable table(&description);
  DefineOptions(&options, &compatibility, &table);
  return table.names();
}

std::string FormatStereoCommandOptions(const StereoCommandOptions& options) {
  StereoCommandOptions copy = options;
  CompatibilityOptions compatibility;
  po::options_description description;
  OptionTable table(&description);
  DefineOptions(&copy, &compatibility, &table);
  std::ostringstream stream;
  for (size_t i = 0; i < table.names().size(); ++i) {
    if (!table.IsField(i)) continue;
    stream << table.names()[i] << " = " << table.Print(i) << "\n";
  }
  return stream.str();
}

}  // namespace msp
