// What msp_stereo's command line (option_parser.cc) and the bundled tools'
// (tool_command_line.cc) share, so both behave alike: the help check, the
// help layout, full option names only, no stray words, and boost's errors
// turned into OptionError. Internal to msp_options: it exposes
// Boost.Program_options, which the public headers keep out of sight.
#pragma once

#include <boost/program_options.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace msp {
namespace command_line {

// The help text's layout: 100 columns, descriptions from column 50 at most.
constexpr unsigned kHelpLineLength = 100;
constexpr unsigned kHelpMinDescriptionLength = 50;

// The text of a value as the parsers read it back: true/false for booleans,
// and doubles with the digits needed to give the same double again.
std::string ValueText(const std::string& value);
std::string ValueText(bool value);
std::string ValueText(int value);
std::string ValueText(uint64_t value);
std::string ValueText(double value);

// A default as --help shows it: ValueText, with "" marking an empty string.
template <typename T>
std::string DefaultText(const T& value) {
  const std::string text = ValueText(value);
  return text.empty() ? "\"\"" : text;
}

// The message of one of boost's errors. Boost fills an error's placeholders
// (%value%, %option%, ...) until none is left, so a value that holds its own
// placeholder (an ini line `log_to_stderr=x %value%`) would never end; here
// every '%' of what the input put into the message reads '?'.
std::string ErrorText(const boost::program_options::error& error);

// Lists -h / --help in a help text.
void AddHelpOption(boost::program_options::options_description* description);

// A usage text of option groups, laid out as boost's but never breaking a
// word: boost breaks any word longer than half the description column, and
// option names in help texts are (--MspStereo.advanced_geometric_passes).
// Each group is "<caption>:" (no line when the caption is empty), then one
// entry per option: its name, value and default, then its description,
// wrapped at kHelpLineLength from a column shared by every group.
struct OptionGroupText {
  std::string caption;
  const boost::program_options::options_description* options;
};
std::string FormatOptionGroups(const std::vector<OptionGroupText>& groups);

// True when -h or --help is among the arguments (argv[0] is the program
// name). Help wins over everything else, unknown options next to it included.
bool HasHelpFlag(int argc, const char* const argv[]);

// Parses the arguments into `vm` (without notifying the fields). Option names
// must be spelt in full: an abbreviated or misspelt name is unknown instead of
// silently matching some other option. Bare words fill the options named in
// `positional`, in order; with none, a bare word is an error (boost would drop
// it silently, and it is almost certainly a value whose option name was
// mistyped). With positional options a word starting with one dash is a
// value (a negative number), since no option has a one-letter form but -h.
// Throws OptionError.
void StoreCommandLine(int argc, const char* const argv[],
                      const boost::program_options::options_description& description,
                      const std::vector<std::string>& positional,
                      boost::program_options::variables_map* vm);

// boost::program_options::notify, with boost's errors as OptionError.
void NotifyOptions(boost::program_options::variables_map* vm);

}  // namespace command_line
}  // namespace msp
