#include "options/option_parser.h"

#include <algorithm>
#include <boost/program_options.hpp>
#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

#include "options/command_line_common.h"
#include "options/option_name.h"
#include "options/option_table.h"

namespace msp {
namespace {

namespace po = boost::program_options;

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

// Prints every option, not only the common ones.
constexpr char kHelpAllFlag[] = "--help_all";

// The captions of the advanced options and of the ignored ones in --help_all.
constexpr char kAdvancedHeading[] =
    "Advanced options: the method's numeric internals and its coarse-to-fine schedule";
constexpr char kIgnoredHeading[] = "COLMAP options accepted for compatibility and ignored";

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// An option as an ini file spells it: `field` under [Section], or `name`
// before any section.
std::string IniSpelling(const std::string& name) {
  const size_t dot = name.find('.');
  if (dot == std::string::npos) return "`" + name + "` before any section";
  return "`" + name.substr(dot + 1) + "` under [" + name.substr(0, dot) + "]";
}

// An option of an earlier version given on the command line stops with the
// name it has now (a value that happens to start with "--" counts too, which
// no value of an option of ours does).
void RefuseRenamedOptions(int argc, const char* const argv[], const OptionTable& table) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (!StartsWith(arg, "--")) continue;
    const std::string name = arg.substr(2, arg.find('=') - 2);
    const std::string renamed = table.RenamedTo(name);
    if (!renamed.empty()) {
      throw OptionError("option --" + name + " was renamed --" + renamed);
    }
  }
}

// Reads the ini file into `vm`. Values already in `vm` (from the command line)
// win, because boost's store() never overwrites a stored value.
void StoreIniFile(const std::string& path, const OptionTable& table, po::variables_map* vm) {
  const std::string in_file =
      MSP_OPTION_FLAG_OF(StereoCommandOptions, project_path) + " file `" + path + "`";
  std::ifstream file(path);
  if (!file) throw OptionError("cannot open " + in_file);
  const po::options_description description = table.All();
  po::parsed_options parsed(&description);
  try {
    parsed = po::parse_config_file(file, description, /*allow_unregistered=*/true);
  } catch (const po::error& e) {
    throw OptionError("in " + in_file + ": " + command_line::ErrorText(e));
  }
  std::vector<po::option> known;
  for (const po::option& option : parsed.options) {
    if (!option.unregistered) {
      known.push_back(option);
      continue;
    }
    const std::string renamed = table.RenamedTo(option.string_key);
    if (!renamed.empty()) {
      throw OptionError("option " + IniSpelling(option.string_key) + " in " + in_file +
                        " was renamed: use " + IniSpelling(renamed));
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
    throw OptionError("in " + in_file + ": " + command_line::ErrorText(e));
  }
}

std::string ToUpper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  return text;
}

}  // namespace

ParseStatus ParseStereoCommand(int argc, const char* const argv[], StereoCommandOptions* options) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == kHelpAllFlag) return ParseStatus::kHelpAll;
  }
  if (command_line::HasHelpFlag(argc, argv)) return ParseStatus::kHelp;

  OptionTable table;
  DefineStereoCommandOptions(options, &table);
  RefuseRenamedOptions(argc, argv, table);

  // COLMAP commands take no bare words (positional options).
  po::variables_map vm;
  command_line::StoreCommandLine(argc, argv, table.All(), /*positional=*/{}, &vm);
  const std::string project_key = MSP_OPTION_NAME(*options, project_path);
  if (vm.count(project_key) && !vm[project_key].as<std::string>().empty()) {
    StoreIniFile(vm[project_key].as<std::string>(), table, &vm);
  }
  command_line::NotifyOptions(&vm);

  const std::string workspace_key = MSP_OPTION_NAME(*options, workspace_path);
  if (!vm.count(workspace_key) || options->workspace_path.empty()) {
    throw OptionError("missing required option " + MSP_OPTION_FLAG(*options, workspace_path));
  }
  ApplySharedOptions(options);
  return ParseStatus::kRun;
}

void ApplySharedOptions(StereoCommandOptions* options) {
  options->msp.seed = options->random_seed;
  options->msp.num_threads = options->patch_match.num_threads;
  options->workspace_format = ToUpper(options->workspace_format);
}

std::string StereoCommandUsage(UsageScope scope) {
  StereoCommandOptions options;
  OptionTable table;
  DefineStereoCommandOptions(&options, &table);
  po::options_description help;
  command_line::AddHelpOption(&help);
  help.add_options()(kHelpAllFlag + 2,
                     "Print every option, the advanced ones and the COLMAP options that are "
                     "accepted and ignored included, and exit.");
  po::options_description first;  // the help options, then the common ones
  first.add(help).add(table.Description(OptionGroup::kCommon));
  std::vector<command_line::OptionGroupText> groups = {{"Options", &first}};
  if (scope == UsageScope::kAllOptions) {
    groups.push_back({kAdvancedHeading, &table.Description(OptionGroup::kAdvanced)});
    groups.push_back({kIgnoredHeading, &table.Description(OptionGroup::kIgnored)});
  }
  std::ostringstream stream;
  stream << "Usage: msp_stereo --workspace_path <dense workspace> [options]\n"
            "       colmap msp_stereo --workspace_path <dense workspace> [options]\n\n"
            "Dense stereo for a COLMAP workspace; writes stereo/{depth,normal}_maps like\n"
            "`colmap patch_match_stereo`. Options come from the command line or from the\n"
            "[PatchMatchStereo] / [MspStereo] sections of a --project_path ini file; the\n"
            "command line overrides the ini file.\n\n"
         << command_line::FormatOptionGroups(groups);
  if (scope == UsageScope::kCommonOptions) {
    const size_t more = table.Description(OptionGroup::kAdvanced).options().size() +
                        table.Description(OptionGroup::kIgnored).options().size();
    stream << "\n"
           << kHelpAllFlag << " lists " << more
           << " more options: the advanced ones (--MspStereo.advanced_*) and the COLMAP\n"
              "options that are accepted and ignored.\n";
  }
  return stream.str();
}

std::vector<std::string> StereoCommandOptionNames() {
  StereoCommandOptions options;
  OptionTable table;
  DefineStereoCommandOptions(&options, &table);
  return table.names();
}

void PrintStereoCommandOptions(const StereoCommandOptions& options, std::ostream& out) {
  // The table binds to fields it may write through; it only reads this copy.
  StereoCommandOptions copy = options;
  OptionTable table;
  DefineStereoCommandOptions(&copy, &table);
  for (size_t i = 0; i < table.names().size(); ++i) {
    out << "--" << table.names()[i] << " " << ShellWord(table.Value(i)) << "\n";
  }
}

}  // namespace msp
