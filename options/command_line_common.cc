#include "options/command_line_common.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

#include "options/option_parser.h"

namespace msp {
namespace command_line {
namespace {

namespace po = boost::program_options;

// Reads the substitutions of an error (a protected member of boost's base
// class): they hold the text that came from the input.
struct SubstitutionsOf : po::error_with_option_name {
  static const std::map<std::string, std::string>& Of(const po::error_with_option_name& error) {
    return error.*(&SubstitutionsOf::m_substitutions);
  }
};

[[noreturn]] void ThrowOptionError(const po::error& error) {
  if (const auto* unknown = dynamic_cast<const po::unknown_option*>(&error)) {
    throw OptionError("unknown option `" + unknown->get_option_name() +
                      "` (run with --help to list the options)");
  }
  if (const auto* required = dynamic_cast<const po::required_option*>(&error)) {
    throw OptionError("missing required option " + required->get_option_name());
  }
  throw OptionError(ErrorText(error));
}

}  // namespace

std::string ErrorText(const po::error& error) {
  const auto* named = dynamic_cast<const po::error_with_option_name*>(&error);
  if (named == nullptr) return error.what();
  po::error_with_option_name safe(*named);
  for (const auto& [key, value] : SubstitutionsOf::Of(*named)) {
    std::string text = value;
    std::replace(text.begin(), text.end(), '%', '?');
    safe.set_substitute(key, text);
  }
  return safe.what();
}

std::string ValueText(const std::string& value) { return value; }
std::string ValueText(bool value) { return value ? "true" : "false"; }
std::string ValueText(int value) { return std::to_string(value); }
std::string ValueText(uint64_t value) { return std::to_string(value); }
std::string ValueText(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.15g", value);
  if (std::strtod(text, nullptr) != value) std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

void AddHelpOption(po::options_description* description) {
  description->add_options()("help,h", "Print this help and exit.");
}

namespace {

// "  --name arg (=default)", the left column of an option's entry.
std::string NameText(const po::option_description& option) {
  std::string text = "  " + option.format_name();
  const std::string parameter = option.format_parameter();
  if (!parameter.empty()) text += " " + parameter;
  return text;
}

// `text` wrapped into lines of at most `width` characters at spaces; a word
// longer than `width` gets a line of its own.
std::vector<std::string> WrapWords(const std::string& text, size_t width) {
  std::vector<std::string> lines(1);
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    std::string& line = lines.back();
    if (line.empty()) {
      line = word;
    } else if (line.size() + 1 + word.size() <= width) {
      line += " " + word;
    } else {
      lines.push_back(word);
    }
  }
  return lines;
}

}  // namespace

std::string FormatOptionGroups(const std::vector<OptionGroupText>& groups) {
  // The descriptions start two spaces after the longest name, but leave at
  // least kHelpMinDescriptionLength columns; longer names go on a line of
  // their own.
  size_t column = 0;
  for (const OptionGroupText& group : groups) {
    for (const auto& option : group.options->options()) {
      column = std::max(column, NameText(*option).size() + 2);
    }
  }
  column = std::min<size_t>(column, kHelpLineLength - kHelpMinDescriptionLength);
  std::ostringstream out;
  for (size_t g = 0; g < groups.size(); ++g) {
    if (g > 0) out << "\n";
    if (!groups[g].caption.empty()) out << groups[g].caption << ":\n";
    for (const auto& option : groups[g].options->options()) {
      const std::string name = NameText(*option);
      out << name;
      size_t at = name.size();
      if (at + 2 > column) {
        out << "\n";
        at = 0;
      }
      for (const std::string& line : WrapWords(option->description(), kHelpLineLength - column)) {
        out << std::string(column - at, ' ') << line << "\n";
        at = 0;
      }
    }
  }
  return out.str();
}

bool HasHelpFlag(int argc, const char* const argv[]) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") return true;
  }
  return false;
}

void StoreCommandLine(int argc, const char* const argv[],
                      const po::options_description& description,
                      const std::vector<std::string>& positional, po::variables_map* vm) {
  int style = po::command_line_style::unix_style & ~po::command_line_style::allow_guessing;
  if (!positional.empty()) style &= ~po::command_line_style::allow_short;
  try {
    po::parsed_options parsed =
        po::command_line_parser(argc, argv).options(description).style(style).run();
    for (po::option& option : parsed.options) {
      if (option.position_key < 0) continue;
      if (option.position_key >= static_cast<int>(positional.size())) {
        throw OptionError("unexpected argument `" + option.original_tokens.front() +
                          "` (options are --name value; run with --help to list them)");
      }
      option.string_key = positional[option.position_key];
    }
    po::store(parsed, *vm);
  } catch (const po::error& e) {
    ThrowOptionError(e);
  }
}

void NotifyOptions(po::variables_map* vm) {
  try {
    po::notify(*vm);
  } catch (const po::error& e) {
    ThrowOptionError(e);
  }
}

}  // namespace command_line
}  // namespace msp
