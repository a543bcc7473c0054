// The command line of the bundled tools (msp_make_scene, msp_write_gt_maps,
// msp_evaluate, msp_convert_masks, msp_bench_patch_match), on
// Boost.Program_options like msp_stereo's and sharing its rules
// (command_line_common.h): each option is declared once with its field, help
// text and default (the field's value on entry), and the same declarations
// parse the arguments and print --help.
//
// Options take `--name value` or `--name=value`; names must be spelt in full
// (no prefix guessing); an unknown option, a malformed or missing value, a
// repeated option, a bare word (unless positional options take it) or a
// missing required option throws OptionError naming it. Value ranges are the
// tools' own checks.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "options/option_parser.h"

namespace msp {

class ToolCommandLine {
 public:
  // `usage` is the first line of the help text ("Usage: msp_evaluate
  // --workspace <ws> [options]"), `summary` says what the tool does.
  ToolCommandLine(const std::string& usage, const std::string& summary);
  ~ToolCommandLine();
  ToolCommandLine(const ToolCommandLine&) = delete;
  ToolCommandLine& operator=(const ToolCommandLine&) = delete;

  // An option taking a value; the field's value on entry is the default.
  // `default_text`, when not empty, is printed instead of it (for a field
  // whose empty default stands for a derived value, e.g. <ws>/ground_truth).
  void Add(const std::string& name, std::string* field, const std::string& help,
           const std::string& default_text = "");
  void Add(const std::string& name, int* field, const std::string& help);
  void Add(const std::string& name, double* field, const std::string& help);
  // Digits only: "-1" is an error, not 2^64 - 1.
  void Add(const std::string& name, uint64_t* field, const std::string& help);
  // A string option whose value must be one of `choices` (the default too).
  void AddChoice(const std::string& name, std::string* field,
                 const std::vector<std::string>& choices, const std::string& help);
  // A string option without a default that must be given.
  void AddRequired(const std::string& name, std::string* field, const std::string& help);
  // An option without a value: when given, *field becomes `value_when_given`.
  void AddFlag(const std::string& name, bool* field, bool value_when_given,
               const std::string& help);

  // Bare words fill these options (declared already, each taking a value) in
  // order: with {"width", "height"}, `tool 640 480` is `tool --width 640
  // --height 480`. A word beyond them is an error; so is an option given
  // both ways. Throws std::invalid_argument for an undeclared name.
  void SetPositional(const std::vector<std::string>& names);

  // Parses `argv` (argv[0] is the program name) into the fields. Returns
  // kHelp, touching no field, when -h or --help is among the arguments.
  ParseStatus Parse(int argc, const char* const argv[]) const;

  // The help text: usage, summary and every option with its default.
  std::string Usage() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace msp
