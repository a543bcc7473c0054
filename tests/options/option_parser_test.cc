#include "options/option_parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

// Every --PatchMatchStereo.* option of COLMAP 3.8, listed independently of
// the parser so a dropped or renamed option is caught.
const std::vector<std::string> kColmapPatchMatchFields = {
    "max_image_size",
    "gpu_index",
    "depth_min",
    "depth_max",
    "window_radius",
    "window_step",
    "sigma_spatial",
    "sigma_color",
    "num_samples",
    "ncc_sigma",
    "min_triangulation_angle",
    "incident_angle_sigma",
    "num_iterations",
    "geom_consistency",
    "geom_consistency_regularizer",
    "geom_consistency_max_cost",
    "filter",
    "filter_min_ncc",
    "filter_min_triangulation_angle",
    "filter_min_num_consistent",
    "filter_geom_consistency_max_cost",
    "cache_size",
    "allow_missing_files",
    "write_consistency_graph",
};
// --MspStereo.<field>: the common options, then (without their prefix) the
// advanced ones, --MspStereo.advanced_<field>.
const std::vector<std::string> kMspFields = {"backend",
                                             "mask_path",
                                             "window_step",
                                             "bilateral_ncc",
                                             "deformable",
                                             "equidistribution",
                                             "segmentation_prior",
                                             "edge_aggregation",
                                             "edge_refinement",
                                             "write_previews",
                                             "disassemble_clustering",
                                             "synergistic_optimization"};
const std::vector<std::string> kMspAdvancedFields = {"coarsest_image_size",
                                                     "iterations",
                                                     "finest_iterations",
                                                     "geometric_passes",
                                                     "finest_geometric_passes",
                                                     "restoring_image_size",
                                                     "deformable_max_image_size",
                                                     "finest_refine_radius",
                                                     "finest_hold_weak_texture",
                                                     "finest_deformable",
                                                     "weighted_views_only",
                                                     "joint_bilateral_upsampling",
                                                     "reliable_max_cost",
                                                     "reliable_single_cost",
                                                     "reliable_min_spread",
                                                     "anchor_max_distance",
                                                     "equidistribution_iterations",
                                                     "num_mask_levels",
                                                     "crf_alpha",
                                                     "crf_beta",
                                                     "crf_unary_confidence",
                                                     "crf_iterations",
                                                     "dbscan_eta",
                                                     "dbscan_gamma",
                                                     "sampling_solutions",
                                                     "sampling_local_search",
                                                     "disparity_samples",
                                                     "disparity_step",
                                                     "variance_weight",
                                                     "profile_cost_term"};
// COLMAP options that are accepted and ignored: --help_all lists them, --help does not.
const std::vector<std::string> kIgnored = {
    "pmvs_option_name",
    "log_to_stderr",
    "PatchMatchStereo.window_step",
    "PatchMatchStereo.ncc_sigma",
    "PatchMatchStereo.incident_angle_sigma",
    "PatchMatchStereo.num_iterations",
    "PatchMatchStereo.write_consistency_graph",
};
const std::vector<std::string> kTopLevel = {
    "workspace_path", "workspace_format", "pmvs_option_name", "config_path",
    "project_path",   "random_seed",      "log_to_stderr",    "log_level"};

// Parses `args` (without the program name) into fresh defaults.
StereoCommandOptions Parse(std::vector<std::string> args, ParseStatus* status = nullptr) {
  args.insert(args.begin(), "msp_stereo");
  std::vector<const char*> argv;
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  StereoCommandOptions options;
  const ParseStatus result =
      ParseStereoCommand(static_cast<int>(argv.size()), argv.data(), &options);
  if (status != nullptr) *status = result;
  return options;
}

// The message of the OptionError the parser throws, or "" if none.
std::string ParseError(const std::vector<std::string>& args) {
  return test::ErrorMessage<OptionError>([&] { Parse(args); });
}

// An ini file in a scratch folder removed at the end of the test.
class IniFile {
 public:
  explicit IniFile(const std::string& text) { test::WriteRaw(path(), text); }
  std::string path() const { return dir_ / "project.ini"; }

 private:
  test::TempDir dir_;
};

TEST(OptionParser, DefaultsEqualColmap) {
  const PatchMatchStereoOptions p = Parse({"--workspace_path", "ws"}).patch_match;
  // COLMAP 3.8 src/mvs/patch_match.h initialisers.
  EXPECT_EQ(p.max_image_size, -1);
  EXPECT_EQ(p.gpu_index, "-1");
  EXPECT_EQ(p.depth_min, -1.0);
  EXPECT_EQ(p.depth_max, -1.0);
  EXPECT_EQ(p.window_radius, 5);
  EXPECT_EQ(p.window_step, 1);
  EXPECT_EQ(p.sigma_spatial, -1.0);
  EXPECT_DOUBLE_EQ(p.sigma_color, 0.2);
  EXPECT_EQ(p.num_samples, 15);
  EXPECT_DOUBLE_EQ(p.ncc_sigma, 0.6);
  EXPECT_DOUBLE_EQ(p.min_triangulation_angle, 1.0);
  EXPECT_DOUBLE_EQ(p.incident_angle_sigma, 0.9);
  EXPECT_EQ(p.num_iterations, 5);
  EXPECT_TRUE(p.geom_consistency);
  EXPECT_DOUBLE_EQ(p.geom_consistency_regularizer, 0.3);
  EXPECT_DOUBLE_EQ(p.geom_consistency_max_cost, 3.0);
  EXPECT_TRUE(p.filter);
  EXPECT_DOUBLE_EQ(p.filter_min_ncc, 0.1);
  EXPECT_DOUBLE_EQ(p.filter_min_triangulation_angle, 3.0);
  EXPECT_EQ(p.filter_min_num_consistent, 2);
  EXPECT_DOUBLE_EQ(p.filter_geom_consistency_max_cost, 1.0);
  EXPECT_DOUBLE_EQ(p.cache_size, 32.0);
  EXPECT_FALSE(p.allow_missing_files);
  EXPECT_FALSE(p.write_consistency_graph);

  const StereoCommandOptions o = Parse({"--workspace_path", "ws"});
  EXPECT_EQ(o.workspace_path, "ws");
  EXPECT_EQ(o.workspace_format, "COLMAP");
  EXPECT_EQ(o.pmvs_option_name, "option-all");
  EXPECT_EQ(o.config_path, "");
  EXPECT_EQ(o.msp.backend, "auto");
  EXPECT_EQ(o.msp.seed, 0);
}

TEST(OptionParser, ParsesColmapCommandLine) {
  // The first line of COLMAP's run-colmap-geometric.sh.
  const StereoCommandOptions o = Parse({"--workspace_path", ".", "--workspace_format", "COLMAP",
                                        "--PatchMatchStereo.max_image_size", "2000",
                                        "--PatchMatchStereo.geom_consistency", "true"});
  EXPECT_EQ(o.workspace_path, ".");
  EXPECT_EQ(o.patch_match.max_image_size, 2000);
  EXPECT_TRUE(o.patch_match.geom_consistency);
  EXPECT_FALSE(Parse({"--workspace_path", ".", "--PatchMatchStereo.geom_consistency", "false"})
                   .patch_match.geom_consistency);
}

TEST(OptionParser, ParsesEveryKindOfValue) {
  const StereoCommandOptions o = Parse({"--workspace_path=/data/ws",
                                        "--workspace_format",
                                        "pmvs",
                                        "--pmvs_option_name",
                                        "opt",
                                        "--config_path",
                                        "my.cfg",
                                        "--PatchMatchStereo.depth_min",
                                        "-1",
                                        "--PatchMatchStereo.depth_max",
                                        "-1",
                                        "--PatchMatchStereo.gpu_index",
                                        "0,1",
                                        "--PatchMatchStereo.window_radius",
                                        "7",
                                        "--PatchMatchStereo.sigma_color=0.5",
                                        "--PatchMatchStereo.filter",
                                        "0",
                                        "--PatchMatchStereo.allow_missing_files",
                                        "1",
                                        "--MspStereo.backend",
                                        "cuda",
                                        "--random_seed",
                                        "42",
                                        "--MspStereo.mask_path",
                                        "m",
                                        "--log_to_stderr",
                                        "1",
                                        "--log_level",
                                        "0",
                                        "--PatchMatchStereo.num_threads",
                                        "4"});
  EXPECT_EQ(o.workspace_path, "/data/ws");
  EXPECT_EQ(o.workspace_format, "PMVS");  // normalised, COLMAP is case-insensitive here
  EXPECT_EQ(o.pmvs_option_name, "opt");
  EXPECT_EQ(o.config_path, "my.cfg");
  EXPECT_EQ(o.patch_match.depth_min, -1.0);  // a negative value as a separate token
  EXPECT_EQ(o.patch_match.gpu_index, "0,1");
  EXPECT_EQ(o.patch_match.window_radius, 7);
  EXPECT_DOUBLE_EQ(o.patch_match.sigma_color, 0.5);
  EXPECT_FALSE(o.patch_match.filter);
  EXPECT_TRUE(o.patch_match.allow_missing_files);
  EXPECT_EQ(o.msp.backend, "cuda");
  EXPECT_EQ(o.msp.seed, 42);
  EXPECT_EQ(o.msp.num_threads, 4);
  EXPECT_EQ(o.msp.mask_path, "m");
}

// COLMAP's options are the only names of the seed and the thread count; the
// back-ends read them from options.msp.
TEST(OptionParser, RandomSeedAndNumThreadsReachTheBackEnds) {
  const StereoCommandOptions o =
      Parse({"--workspace_path", "w", "--random_seed", "7", "--PatchMatchStereo.num_threads", "3"});
  EXPECT_EQ(o.msp.seed, 7);
  EXPECT_EQ(o.msp.num_threads, 3);
  EXPECT_EQ(Parse({"--workspace_path", "w"}).msp.num_threads, -1);
}

// An option of an earlier version stops with the name it has now, on the
// command line and in an ini file.
TEST(OptionParser, RenamedOptionsNameTheirNewName) {
  EXPECT_EQ(ParseError({"--workspace_path", "w", "--MspStereo.seed", "3"}),
            "option --MspStereo.seed was renamed --random_seed");
  EXPECT_EQ(ParseError({"--workspace_path", "w", "--MspStereo.num_threads=2"}),
            "option --MspStereo.num_threads was renamed --PatchMatchStereo.num_threads");
  for (const std::string& field : kMspAdvancedFields) {
    EXPECT_EQ(ParseError({"--workspace_path", "w", "--MspStereo." + field, "1"}),
              "option --MspStereo." + field + " was renamed --MspStereo.advanced_" + field);
  }
  const IniFile seed("workspace_path=w\n[MspStereo]\nseed=11\n");
  EXPECT_EQ(ParseError({"--project_path", seed.path()}),
            "option `seed` under [MspStereo] in --project_path file `" + seed.path() +
                "` was renamed: use `random_seed` before any section");
  const IniFile crf("workspace_path=w\n[MspStereo]\ncrf_alpha=0.1\n");
  EXPECT_EQ(ParseError({"--project_path", crf.path()}),
            "option `crf_alpha` under [MspStereo] in --project_path file `" + crf.path() +
                "` was renamed: use `advanced_crf_alpha` under [MspStereo]");
}

TEST(OptionParser, ReadsIniWithBothSections) {
  const IniFile ini(
      "workspace_path=/from/ini\n"
      "random_seed=11\n"
      "database_path=/ignored/db\n"
      "[SiftExtraction]\n"
      "use_gpu=false\n"
      "[PatchMatchStereo]\n"
      "window_radius=9\n"
      "geom_consistency=false\n"
      "filter = 0\n"
      "depth_min=0.5\n"
      "depth_max=10\n"
      "[MspStereo]\n"
      "backend=cuda\n");
  const StereoCommandOptions o = Parse({"--project_path", ini.path()});
  EXPECT_EQ(o.workspace_path, "/from/ini");
  EXPECT_EQ(o.patch_match.window_radius, 9);
  EXPECT_FALSE(o.patch_match.geom_consistency);
  EXPECT_FALSE(o.patch_match.filter);
  EXPECT_DOUBLE_EQ(o.patch_match.depth_min, 0.5);
  EXPECT_DOUBLE_EQ(o.patch_match.depth_max, 10.0);
  EXPECT_EQ(o.msp.backend, "cuda");
  EXPECT_EQ(o.msp.seed, 11);
  EXPECT_EQ(o.patch_match.num_samples, 15);  // untouched default
}

TEST(OptionParser, ReadsColmapProjectIni) {
  // An excerpt of what `colmap project_generator` (3.8) writes: top-level keys,
  // sections of other commands and a full [PatchMatchStereo] section.
  const IniFile ini(
      "log_to_stderr=false\nrandom_seed=0\nlog_level=2\ndatabase_path=\nimage_path=\n"
      "[ImageReader]\nsingle_camera=false\n"
      "[PatchMatchStereo]\ngeom_consistency=true\nfilter=true\nallow_missing_files=false\n"
      "write_consistency_graph=false\nmax_image_size=2400\nwindow_radius=5\nwindow_step=1\n"
      "num_samples=15\nnum_iterations=5\nfilter_min_num_consistent=2\ndepth_min=-1\n"
      "depth_max=-1\nsigma_spatial=-1\nsigma_color=0.20000000298023224\n"
      "ncc_sigma=0.60000002384185791\nmin_triangulation_angle=1\n"
      "incident_angle_sigma=0.89999997615814209\n"
      "geom_consistency_regularizer=0.30000001192092896\ngeom_consistency_max_cost=3\n"
      "filter_min_ncc=0.10000000149011612\nfilter_min_triangulation_angle=3\n"
      "filter_geom_consistency_max_cost=1\ncache_size=32\ngpu_index=-1\n"
      "[StereoFusion]\nuse_cache=false\nmax_image_size=2400\n");
  const StereoCommandOptions o = Parse({"--project_path", ini.path(), "--workspace_path", "w"});
  EXPECT_EQ(o.patch_match.max_image_size, 2400);
  EXPECT_NEAR(o.patch_match.sigma_color, 0.2, 1e-6);
  EXPECT_TRUE(o.patch_match.geom_consistency);
}

TEST(OptionParser, CommandLineOverridesIni) {
  const IniFile ini(
      "workspace_path=/from/ini\nrandom_seed=11\n"
      "[PatchMatchStereo]\nwindow_radius=9\nnum_samples=4\ngeom_consistency=true\n");
  const StereoCommandOptions o =
      Parse({"--PatchMatchStereo.window_radius", "3", "--project_path", ini.path(),
             "--workspace_path", "/from/cli", "--PatchMatchStereo.geom_consistency", "0"});
  EXPECT_EQ(o.workspace_path, "/from/cli");
  EXPECT_EQ(o.patch_match.window_radius, 3);
  EXPECT_FALSE(o.patch_match.geom_consistency);
  EXPECT_EQ(o.patch_match.num_samples, 4);  // from the ini, not given on the command line
  EXPECT_EQ(o.msp.seed, 11);
}

TEST(OptionParser, IniErrorsNameTheProblem) {
  const IniFile typo("workspace_path=w\n[PatchMatchStereo]\nwindow_radiuss=3\n");
  EXPECT_NE(ParseError({"--project_path", typo.path()}).find("PatchMatchStereo.window_radiuss"),
            std::string::npos);
  const IniFile bad_bool("workspace_path=w\n[PatchMatchStereo]\nfilter=maybe\n");
  EXPECT_NE(ParseError({"--project_path", bad_bool.path()}).find("maybe"), std::string::npos);
  EXPECT_NE(
      ParseError({"--project_path", "/nonexistent/project.ini"}).find("/nonexistent/project.ini"),
      std::string::npos);
}

// Boost fills an error's placeholders until none is left: a value holding its
// own placeholder hung the parser (found by project_ini_fuzzer). The message
// comes at once, the value's '%' read as '?'.
TEST(OptionParser, ValuesThatLookLikePlaceholdersGiveAMessage) {
  const IniFile ini("workspace_path=w\nlog_to_stderr=false ('%value%')\n");
  const std::string in_ini = ParseError({"--project_path", ini.path()});
  EXPECT_NE(in_ini.find("false ('?value?')"), std::string::npos) << in_ini;
  EXPECT_NE(in_ini.find("log_to_stderr"), std::string::npos) << in_ini;
  const std::string on_command_line =
      ParseError({"--workspace_path", "w", "--PatchMatchStereo.window_radius", "%value%5"});
  EXPECT_NE(on_command_line.find("?value?5"), std::string::npos) << on_command_line;
  const std::string in_name = ParseError({"--workspace_path", "w", "--x%option%", "1"});
  EXPECT_NE(in_name.find("x%option%"), std::string::npos) << in_name;
}

TEST(OptionParser, UnknownOptionIsNamed) {
  const std::string error =
      ParseError({"--workspace_path", "w", "--PatchMatchStereo.window_size", "3"});
  EXPECT_NE(error.find("unknown option"), std::string::npos) << error;
  EXPECT_NE(error.find("--PatchMatchStereo.window_size"), std::string::npos) << error;
  // No prefix guessing: an abbreviation is unknown, not silently expanded.
  EXPECT_NE(ParseError({"--workspace", "w"}).find("--workspace"), std::string::npos);
  EXPECT_NE(ParseError({"--workspace_path", "w", "stray"}), "");
}

TEST(OptionParser, BadValuesAreErrors) {
  EXPECT_NE(ParseError({"--workspace_path", "w", "--PatchMatchStereo.window_radius", "five"})
                .find("window_radius"),
            std::string::npos);
  EXPECT_NE(ParseError({"--workspace_path", "w", "--PatchMatchStereo.filter", "yes please"}), "");
  EXPECT_NE(ParseError({"--workspace_path", "w", "--PatchMatchStereo.window_radius"}), "");
}

TEST(OptionParser, WorkspacePathIsRequired) {
  EXPECT_NE(ParseError({}).find("--workspace_path"), std::string::npos);
  EXPECT_NE(ParseError({"--PatchMatchStereo.window_radius", "3"}).find("--workspace_path"),
            std::string::npos);
}

TEST(OptionParser, HelpWinsAndListsEveryOption) {
  ParseStatus status = ParseStatus::kRun;
  Parse({"--help"}, &status);
  EXPECT_EQ(status, ParseStatus::kHelp);
  Parse({"--no_such_option", "-h"}, &status);
  EXPECT_EQ(status, ParseStatus::kHelp);
  Parse({"--help", "--help_all"}, &status);
  EXPECT_EQ(status, ParseStatus::kHelpAll);

  const std::string usage = StereoCommandUsage(UsageScope::kAllOptions);
  std::vector<std::string> expected = kTopLevel;
  for (const std::string& f : kColmapPatchMatchFields) expected.push_back("PatchMatchStereo." + f);
  for (const std::string& f : kMspFields) expected.push_back("MspStereo." + f);
  for (const std::string& f : kMspAdvancedFields) expected.push_back("MspStereo.advanced_" + f);
  for (const std::string& name : expected) {
    EXPECT_NE(usage.find("--" + name + " "), std::string::npos) << name;
  }
  // Defaults and help text are shown.
  EXPECT_NE(usage.find("--PatchMatchStereo.window_radius arg (=5)"), std::string::npos) << usage;
  EXPECT_NE(usage.find("--PatchMatchStereo.sigma_color arg (=0.2)"), std::string::npos) << usage;
  EXPECT_NE(usage.find("--PatchMatchStereo.geom_consistency arg (=true)"), std::string::npos);
  EXPECT_NE(usage.find("Half window size"), std::string::npos);
  EXPECT_NE(usage.find("--MspStereo.backend arg (=auto)"), std::string::npos);
  // No line is wider than the help layout, and no word is broken.
  std::istringstream lines(usage);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_LE(line.size(), 100u) << line;
  }
  EXPECT_NE(usage.find(" --MspStereo.advanced_geometric_passes "), std::string::npos) << usage;
}

// --help lists the common options only, and says how many more --help_all lists.
TEST(OptionParser, HelpLeavesTheAdvancedAndIgnoredOptionsToHelpAll) {
  const std::string usage = StereoCommandUsage();
  // An option's entry starts a line; help texts may name other options.
  const auto lists = [](const std::string& usage, const std::string& name) {
    return usage.find("\n  --" + name + " ") != std::string::npos;
  };
  for (const std::string& f : kMspFields) EXPECT_TRUE(lists(usage, "MspStereo." + f)) << f;
  EXPECT_TRUE(lists(usage, "PatchMatchStereo.window_radius"));
  for (const std::string& f : kMspAdvancedFields) {
    EXPECT_FALSE(lists(usage, "MspStereo.advanced_" + f)) << f;
  }
  for (const std::string& name : kIgnored) {
    EXPECT_FALSE(lists(usage, name)) << name;
    EXPECT_TRUE(lists(StereoCommandUsage(UsageScope::kAllOptions), name)) << name;
  }
  EXPECT_NE(
      usage.find("--help_all lists " + std::to_string(kMspAdvancedFields.size() + kIgnored.size()) +
                 " more options"),
      std::string::npos)
      << usage;
}

TEST(OptionParser, EveryListedOptionParses) {
  const std::vector<std::string> names = StereoCommandOptionNames();
  for (const std::string& f : kColmapPatchMatchFields) {
    EXPECT_NE(std::find(names.begin(), names.end(), "PatchMatchStereo." + f), names.end()) << f;
  }
  for (const std::string& f : kMspFields) {
    EXPECT_NE(std::find(names.begin(), names.end(), "MspStereo." + f), names.end()) << f;
  }
  for (const std::string& f : kMspAdvancedFields) {
    EXPECT_NE(std::find(names.begin(), names.end(), "MspStereo.advanced_" + f), names.end()) << f;
  }
  // Each option accepts a value of its type on the command line.
  for (const std::string& name : names) {
    if (name == "workspace_path" || name == "project_path") continue;
    const std::string value = name.find("backend") != std::string::npos ? "cpu" : "1";
    EXPECT_EQ(ParseError({"--workspace_path", "w", "--" + name, value}), "") << name;
  }
}

// PrintStereoCommandOptions as lines.
std::vector<std::string> PrintedLines(const StereoCommandOptions& options) {
  std::ostringstream out;
  PrintStereoCommandOptions(options, out);
  std::istringstream in(out.str());
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The arguments a POSIX shell makes of `line` (quotes and backslashes only).
std::vector<std::string> ShellWords(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (ch == ' ') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else if (ch == '\'') {
      const size_t end = line.find('\'', i + 1);
      if (end == std::string::npos) {
        ADD_FAILURE() << "unterminated quote in " << line;
        break;
      }
      word += line.substr(i + 1, end - i - 1);
      i = end;
      in_word = true;
    } else if (ch == '\\' && i + 1 < line.size()) {
      word += line[++i];
      in_word = true;
    } else {
      word += ch;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

TEST(OptionParser, PrintListsEveryRegisteredOptionOnceWithItsValue) {
  const std::vector<std::string> names = StereoCommandOptionNames();
  const std::vector<std::string> lines =
      PrintedLines(Parse({"--workspace_path", "w", "--PatchMatchStereo.window_radius", "8"}));
  ASSERT_EQ(lines.size(), names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(lines[i].rfind("--" + names[i] + " ", 0), 0u) << lines[i];
    EXPECT_EQ(std::count(names.begin(), names.end(), names[i]), 1) << names[i];
  }
  const auto has = [&](const std::string& line) {
    return std::find(lines.begin(), lines.end(), line) != lines.end();
  };
  EXPECT_TRUE(has("--workspace_path w"));
  EXPECT_TRUE(has("--PatchMatchStereo.window_radius 8"));
  EXPECT_TRUE(has("--PatchMatchStereo.sigma_color 0.2"));
  EXPECT_TRUE(has("--PatchMatchStereo.geom_consistency true"));
  EXPECT_TRUE(has("--PatchMatchStereo.num_threads -1"));
  EXPECT_TRUE(has("--PatchMatchStereo.num_iterations 5"));  // accepted, ignored: still listed
  EXPECT_TRUE(has("--MspStereo.backend auto"));
  EXPECT_TRUE(has("--MspStereo.mask_path ''"));
  EXPECT_TRUE(has("--MspStereo.advanced_joint_bilateral_upsampling true"));
  EXPECT_TRUE(has("--log_level 2"));
}

TEST(OptionParser, PrintedValuesRoundTripThroughTheParser) {
  const std::vector<std::string> given = {"--workspace_path",
                                          "/data/my ws/it's here",
                                          "--workspace_format",
                                          "pmvs",
                                          "--config_path",
                                          "",
                                          "--random_seed",
                                          "9",
                                          "--PatchMatchStereo.depth_min",
                                          "0.1",
                                          "--PatchMatchStereo.depth_max",
                                          "12.300000000000001",
                                          "--PatchMatchStereo.sigma_color",
                                          "0.30000000000000004",
                                          "--PatchMatchStereo.filter_min_ncc",
                                          "-0.25",
                                          "--PatchMatchStereo.gpu_index",
                                          "0,1",
                                          "--PatchMatchStereo.filter",
                                          "0",
                                          "--MspStereo.mask_path",
                                          "masks; rm -rf x",
                                          "--MspStereo.advanced_crf_alpha",
                                          "1e-07",
                                          "--PatchMatchStereo.num_threads",
                                          "3"};
  const StereoCommandOptions first = Parse(given);
  const std::vector<std::string> printed = PrintedLines(first);

  std::vector<std::string> args;
  for (const std::string& line : printed) {
    const std::vector<std::string> words = ShellWords(line);
    ASSERT_EQ(words.size(), 2u) << line;
    args.insert(args.end(), words.begin(), words.end());
  }
  const StereoCommandOptions second = Parse(args);
  EXPECT_EQ(PrintedLines(second), printed);
  EXPECT_EQ(second.workspace_path, "/data/my ws/it's here");
  EXPECT_EQ(second.workspace_format, "PMVS");
  EXPECT_EQ(second.config_path, "");
  EXPECT_EQ(second.patch_match.depth_max, first.patch_match.depth_max);  // every bit
  EXPECT_EQ(second.patch_match.sigma_color, 0.1 + 0.2);
  EXPECT_EQ(second.patch_match.filter_min_ncc, -0.25);
  EXPECT_EQ(second.patch_match.gpu_index, "0,1");
  EXPECT_FALSE(second.patch_match.filter);
  EXPECT_EQ(second.msp.mask_path, "masks; rm -rf x");
  EXPECT_EQ(second.msp.advanced_crf_alpha, 1e-7);
  EXPECT_EQ(second.msp.num_threads, 3);
  EXPECT_EQ(second.msp.seed, 9);  // from --random_seed, printed as such
}

// The names a visitor hears, and each field's address.
class NameCollector : public OptionVisitor {
 public:
  void Visit(const std::string& name, int* field, const std::string& help, OptionGroup) override {
    Add(name, field, help);
  }
  void Visit(const std::string& name, double* field, const std::string& help,
             OptionGroup) override {
    Add(name, field, help);
  }
  void Visit(const std::string& name, bool* field, const std::string& help, OptionGroup) override {
    Add(name, field, help);
  }
  void Visit(const std::string& name, std::string* field, const std::string& help,
             OptionGroup) override {
    Add(name, field, help);
  }
  std::vector<std::string> names;
  std::vector<const void*> fields;

 private:
  void Add(const std::string& name, const void* field, const std::string& help) {
    EXPECT_FALSE(help.empty()) << name;
    names.push_back(name);
    fields.push_back(field);
  }
};

TEST(OptionParser, VisitorsHearTheParsersOptionsOfEachStruct) {
  StereoCommandOptions options;
  NameCollector visitor;
  VisitPatchMatchStereoOptions(&options.patch_match, &visitor);
  VisitMspStereoOptions(&options.msp, &visitor);
  std::vector<std::string> sections;
  for (const std::string& name : StereoCommandOptionNames()) {
    if (name.find('.') != std::string::npos) sections.push_back(name);
  }
  EXPECT_EQ(visitor.names, sections);
  // The fields are the struct's own, so a visitor can read and write them.
  const char* begin = reinterpret_cast<const char*>(&options);
  for (const void* field : visitor.fields) {
    EXPECT_GE(static_cast<const char*>(field), begin);
    EXPECT_LT(static_cast<const char*>(field), begin + sizeof(options));
  }
  EXPECT_EQ(visitor.fields.front(), &options.patch_match.max_image_size);
}

}  // namespace
}  // namespace msp
