#include "options/tool_command_line.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace msp {
namespace {

// The fields of a tool like msp_evaluate, with their defaults.
struct Fields {
  std::string workspace;
  std::string ground_truth;
  std::string input_type = "geometric";
  int width = 640;
  double scale = 1.0;
  uint64_t seed = 1;
  bool evaluate_maps = true;
};

class ToolCommandLineTest : public ::testing::Test {
 protected:
  ToolCommandLineTest() : command_line_("Usage: tool --workspace <ws> [options]", "A tool.") {
    command_line_.AddRequired("workspace", &fields_.workspace, "Workspace.");
    command_line_.Add("ground_truth", &fields_.ground_truth, "Ground truth.",
                      "<workspace>/ground_truth");
    command_line_.AddChoice("input_type", &fields_.input_type, {"geometric", "photometric"},
                            "Maps.");
    command_line_.Add("width", &fields_.width, "Width.");
    command_line_.Add("scale", &fields_.scale, "Scale.");
    command_line_.Add("seed", &fields_.seed, "Seed.");
    command_line_.AddFlag("no_maps", &fields_.evaluate_maps, /*value_when_given=*/false,
                          "No maps.");
  }

  // Parses `args` (without the program name).
  ParseStatus Parse(std::vector<std::string> args) {
    args.insert(args.begin(), "tool");
    std::vector<const char*> argv;
    for (const std::string& arg : args) argv.push_back(arg.c_str());
    return command_line_.Parse(static_cast<int>(argv.size()), argv.data());
  }

  std::string ParseError(const std::vector<std::string>& args) {
    try {
      Parse(args);
    } catch (const OptionError& e) {
      return e.what();
    }
    return "";
  }

  Fields fields_;
  ToolCommandLine command_line_;
};

TEST_F(ToolCommandLineTest, KeepsDefaultsOfOptionsNotGiven) {
  EXPECT_EQ(Parse({"--workspace", "ws"}), ParseStatus::kRun);
  const Fields defaults;
  EXPECT_EQ(fields_.workspace, "ws");
  EXPECT_EQ(fields_.ground_truth, defaults.ground_truth);
  EXPECT_EQ(fields_.input_type, defaults.input_type);
  EXPECT_EQ(fields_.width, defaults.width);
  EXPECT_EQ(fields_.scale, defaults.scale);
  EXPECT_EQ(fields_.seed, defaults.seed);
  EXPECT_TRUE(fields_.evaluate_maps);
}

TEST_F(ToolCommandLineTest, ParsesEveryKindOfValue) {
  EXPECT_EQ(
      Parse({"--workspace", "ws", "--ground_truth=gt", "--input_type", "photometric", "--width",
             "320", "--scale", "-0.5", "--seed", "18446744073709551615", "--no_maps"}),
      ParseStatus::kRun);
  EXPECT_EQ(fields_.ground_truth, "gt");
  EXPECT_EQ(fields_.input_type, "photometric");
  EXPECT_EQ(fields_.width, 320);
  EXPECT_EQ(fields_.scale, -0.5);  // ranges are the tool's checks
  EXPECT_EQ(fields_.seed, UINT64_MAX);
  EXPECT_FALSE(fields_.evaluate_maps);
}

TEST_F(ToolCommandLineTest, HelpWinsOverEverythingElse) {
  EXPECT_EQ(Parse({"--unknown", "-h"}), ParseStatus::kHelp);
  EXPECT_EQ(Parse({"--help"}), ParseStatus::kHelp);
  EXPECT_TRUE(fields_.workspace.empty());
}

TEST_F(ToolCommandLineTest, UsageListsEveryOptionWithItsDefault) {
  const std::string usage = command_line_.Usage();
  EXPECT_EQ(usage.rfind("Usage: tool --workspace <ws> [options]", 0), 0u);
  for (const char* text :
       {"-h [ --help ]", "--workspace arg", "--ground_truth arg (=<workspace>/ground_truth)",
        "--input_type arg (=geometric)", "{geometric, photometric}", "--width arg (=640)",
        "--scale arg (=1)", "--seed arg (=1)", "--no_maps"}) {
    EXPECT_NE(usage.find(text), std::string::npos) << text << " not in\n" << usage;
  }
}

TEST_F(ToolCommandLineTest, RejectsBadCommandLinesNamingTheOption) {
  EXPECT_EQ(ParseError({}), "missing required option --workspace");
  EXPECT_EQ(ParseError({"--workspace", "ws", "--widht", "3"}),
            "unknown option `--widht` (run with --help to list the options)");
  // No prefix guessing.
  EXPECT_NE(ParseError({"--workspace", "ws", "--wid", "3"}).find("unknown option `--wid`"),
            std::string::npos);
  EXPECT_NE(ParseError({"--workspace", "ws", "--width", "3x"}).find("--width"), std::string::npos);
  EXPECT_NE(ParseError({"--workspace", "ws", "--scale", "big"}).find("--scale"), std::string::npos);
  EXPECT_NE(ParseError({"--workspace", "ws", "--seed", "-1"}).find("--seed"), std::string::npos);
  EXPECT_NE(ParseError({"--workspace", "ws", "--seed", "99999999999999999999"}).find("--seed"),
            std::string::npos);
  EXPECT_NE(ParseError({"--workspace"}).find("--workspace"), std::string::npos);
  EXPECT_NE(ParseError({"--workspace", "ws", "--no_maps=1"}).find("--no_maps"), std::string::npos);
  EXPECT_EQ(ParseError({"--workspace", "ws", "--input_type", "fused"}),
            "--input_type must be one of geometric, photometric, not `fused`");
  EXPECT_EQ(ParseError({"--workspace", "ws", "stray"}),
            "unexpected argument `stray` (options are --name value; run with --help to list "
            "them)");
}

// A tool whose options may also be given as bare words, in order, like
// `msp_bench_patch_match 640 480 10 ncc`.
class PositionalCommandLineTest : public ::testing::Test {
 protected:
  PositionalCommandLineTest() : command_line_("Usage: bench [width height [mode]]", "A bench.") {
    command_line_.Add("width", &width_, "Width.");
    command_line_.Add("height", &height_, "Height.");
    command_line_.AddChoice("mode", &mode_, {"all", "ncc"}, "Mode.");
    command_line_.SetPositional({"width", "height", "mode"});
  }

  std::string ParseError(std::vector<std::string> args) {
    args.insert(args.begin(), "bench");
    std::vector<const char*> argv;
    for (const std::string& arg : args) argv.push_back(arg.c_str());
    try {
      command_line_.Parse(static_cast<int>(argv.size()), argv.data());
    } catch (const OptionError& e) {
      return e.what();
    }
    return "";
  }

  int width_ = 640;
  int height_ = 480;
  std::string mode_ = "all";
  ToolCommandLine command_line_;
};

TEST_F(PositionalCommandLineTest, BareWordsFillTheOptionsInOrder) {
  EXPECT_EQ(ParseError({"320", "240", "ncc"}), "");
  EXPECT_EQ(width_, 320);
  EXPECT_EQ(height_, 240);
  EXPECT_EQ(mode_, "ncc");
}

TEST_F(PositionalCommandLineTest, FewerWordsKeepTheOtherDefaults) {
  EXPECT_EQ(ParseError({"320"}), "");
  EXPECT_EQ(width_, 320);
  EXPECT_EQ(height_, 480);
  EXPECT_EQ(mode_, "all");
}

TEST_F(PositionalCommandLineTest, NamedOptionsStillWork) {
  EXPECT_EQ(ParseError({"320", "--mode", "ncc"}), "");
  EXPECT_EQ(width_, 320);
  EXPECT_EQ(mode_, "ncc");
}

TEST_F(PositionalCommandLineTest, NegativeNumbersAreValues) {
  // Ranges are the tool's checks; a negative number is not an unknown option.
  EXPECT_EQ(ParseError({"-320", "240"}), "");
  EXPECT_EQ(width_, -320);
}

TEST_F(PositionalCommandLineTest, BadWordsAreErrorsNamingTheOption) {
  EXPECT_NE(ParseError({"wide"}).find("--width"), std::string::npos);
  EXPECT_NE(ParseError({"320", "2.5"}).find("--height"), std::string::npos);
  EXPECT_EQ(ParseError({"320", "240", "fast"}), "--mode must be one of all, ncc, not `fast`");
  EXPECT_EQ(ParseError({"320", "240", "ncc", "extra"}),
            "unexpected argument `extra` (options are --name value; run with --help to list "
            "them)");
  EXPECT_NE(ParseError({"320", "--width", "640"}).find("--width"), std::string::npos);
  EXPECT_NE(ParseError({"--widht", "640"}).find("unknown option `--widht`"), std::string::npos);
}

TEST(ToolCommandLine, PositionalOptionsMustBeDeclaredWithAValue) {
  ToolCommandLine command_line("Usage: tool", "A tool.");
  bool flag = false;
  command_line.AddFlag("flag", &flag, true, "Flag.");
  EXPECT_THROW(command_line.SetPositional({"width"}), std::invalid_argument);
  EXPECT_THROW(command_line.SetPositional({"flag"}), std::invalid_argument);
}

}  // namespace
}  // namespace msp
