// Command line and ini parsing of the `msp_stereo` command. The accepted
// options are a superset of `colmap patch_match_stereo` (COLMAP 3.8), so an
// existing patch_match_stereo command line or project.ini works unchanged.
//
// Precedence: defaults, then the ini file given with --project_path, then the
// command line. (COLMAP 3.8 ignores the command line entirely once
// --project_path is given; letting explicit flags win is what users expect
// and keeps every COLMAP invocation valid, since COLMAP never passes both.)
//
// Ini files use COLMAP's layout: top-level keys (workspace_path, ...) and the
// sections [PatchMatchStereo] and [MspStereo]. Other sections and unknown
// top-level keys of a COLMAP project.ini (SiftExtraction, database_path, ...)
// are ignored; an unknown key inside [PatchMatchStereo] or [MspStereo] is an
// error, since it is almost certainly a typo.
#pragma once

#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "options/stereo_options.h"

namespace msp {

// A bad command line, ini file or option value; the message names the option.
class OptionError : public std::runtime_error {
 public:
  explicit OptionError(const std::string& message) : std::runtime_error(message) {}
};

enum class ParseStatus {
  kRun,      // options are filled in; run the command
  kHelp,     // -h / --help was given; print StereoCommandUsage() and exit 0
  kHelpAll,  // --help_all was given; print StereoCommandUsage(kAllOptions) and exit 0
};

// Which options a usage text lists: the common ones (--help), or also the
// advanced ones (--MspStereo.advanced_*) and the COLMAP options that are
// accepted and ignored (--help_all).
enum class UsageScope { kCommonOptions, kAllOptions };

// Parses the arguments of `msp_stereo` (argv[0] is the program name) into
// `options`, which must hold the defaults on entry. Throws OptionError for an
// unknown option, an option of an earlier version that was renamed (the
// message names the new one), a malformed value, an unreadable ini file or a
// missing --workspace_path; then ApplySharedOptions. Value ranges are not
// checked here: see option_check.h.
ParseStatus ParseStereoCommand(int argc, const char* const argv[], StereoCommandOptions* options);

// Copies the options COLMAP gives at the command's level into the fields the
// back-ends read (--random_seed into msp.seed, --PatchMatchStereo.num_threads
// into msp.num_threads) and writes --workspace_format in upper case (COLMAP
// compares it case-insensitively). ParseStereoCommand calls it; so does any
// other way of filling StereoCommandOptions (the Python module).
void ApplySharedOptions(StereoCommandOptions* options);

// Usage text listing the options of `scope` with their defaults and help
// texts, in usage order; the one description of each option (the README's
// option table is generated from the kAllOptions text).
std::string StereoCommandUsage(UsageScope scope = UsageScope::kCommonOptions);

// Where an option is listed: --help shows the common options, --help_all
// also the advanced ones (--MspStereo.advanced_*) and the COLMAP options that
// are accepted and ignored.
enum class OptionGroup { kCommon, kAdvanced, kIgnored };

// Receives the options of a struct one field at a time: the option's full
// name (MSP_OPTION_NAME, e.g. "PatchMatchStereo.window_radius"), the field,
// its help text and its group. The parser's table is one; the Python
// module's attributes are another, so every option is listed once.
class OptionVisitor {
 public:
  virtual ~OptionVisitor() = default;
  virtual void Visit(const std::string& name, int* field, const std::string& help,
                     OptionGroup group) = 0;
  virtual void Visit(const std::string& name, double* field, const std::string& help,
                     OptionGroup group) = 0;
  virtual void Visit(const std::string& name, bool* field, const std::string& help,
                     OptionGroup group) = 0;
  virtual void Visit(const std::string& name, std::string* field, const std::string& help,
                     OptionGroup group) = 0;
};

// Every field of the struct with an option, in usage order.
void VisitPatchMatchStereoOptions(PatchMatchStereoOptions* options, OptionVisitor* visitor);
void VisitMspStereoOptions(MspStereoOptions* options, OptionVisitor* visitor);

// The full names of every option the command accepts, without "--"
// (e.g. "PatchMatchStereo.window_radius"), in usage order.
std::vector<std::string> StereoCommandOptionNames();

// Writes every option the command accepts, one `--<name> <value>` line each in
// usage order, with the values in force (COLMAP prints its options this way);
// msp_stereo prints it at start-up so a run can be reproduced. The names come
// from the table the parser registers, and each value is one POSIX shell word
// the parser reads back unchanged ('' for an empty string, quotes where needed).
void PrintStereoCommandOptions(const StereoCommandOptions& options, std::ostream& out);

}  // namespace msp
