#include "options/tool_command_line.h"

#include <boost/program_options.hpp>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace msp {
namespace {

namespace po = boost::program_options;

// The help text's layout, as msp_stereo's: 100 columns, descriptions from
// column 50 at most.
constexpr unsigned kHelpLineLength = 100;
constexpr unsigned kHelpMinDescriptionLength = 50;

std::string ToText(const std::string& value) { return value.empty() ? "\"\"" : value; }
template <typename T>
std::string ToText(const T& value) {
  std::ostringstream stream;
  stream << value;
  return stream.str();
}

std::string JoinChoices(const std::vector<std::string>& choices) {
  std::string text;
  for (const std::string& choice : choices) text += (text.empty() ? "" : ", ") + choice;
  return text;
}

uint64_t ParseUnsigned(const std::string& name, const std::string& text) {
  const std::string message = "the argument ('" + text + "') for option '--" + name +
                              "' is invalid: expected an integer >= 0";
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
    throw OptionError(message);
  }
  try {
    return std::stoull(text);
  } catch (const std::out_of_range&) {
    throw OptionError(message + " and < 2^64");
  }
}

bool IsHelpFlag(const std::string& arg) { return arg == "-h" || arg == "--help"; }

}  // namespace

struct ToolCommandLine::Impl {
  po::options_description description;
  // Applied after parsing: the value-less flags, which boost stores no value for.
  std::vector<std::function<void(const po::variables_map&)>> flags;

  explicit Impl(const std::string& caption)
      : description(caption, kHelpLineLength, kHelpMinDescriptionLength) {}
};

ToolCommandLine::ToolCommandLine(const std::string& usage, const std::string& summary)
    : impl_(std::make_unique<Impl>(usage + "\n\n" + summary + "\n\nOptions")) {
  impl_->description.add_options()("help,h", "Print this help and exit.");
}

ToolCommandLine::~ToolCommandLine() = default;

void ToolCommandLine::Add(const std::string& name, std::string* field, const std::string& help,
                          const std::string& default_text) {
  impl_->description.add_options()(
      name.c_str(),
      po::value<std::string>(field)->default_value(
          *field, default_text.empty() ? ToText(*field) : default_text),
      help.c_str());
}

void ToolCommandLine::Add(const std::string& name, int* field, const std::string& help) {
  impl_->description.add_options()(
      name.c_str(), po::value<int>(field)->default_value(*field, ToText(*field)), help.c_str());
}

void ToolCommandLine::Add(const std::string& name, double* field, const std::string& help) {
  impl_->description.add_options()(
      name.c_str(), po::value<double>(field)->default_value(*field, ToText(*field)), help.c_str());
}

void ToolCommandLine::Add(const std::string& name, uint64_t* field, const std::string& help) {
  // boost converts "-1" to an unsigned type by wrapping it; read the text and
  // convert it here instead.
  impl_->description.add_options()(name.c_str(),
                                   po::value<std::string>()
                                       ->default_value(ToText(*field))
                                       ->notifier([name, field](const std::string& text) {
                                         *field = ParseUnsigned(name, text);
                                       }),
                                   help.c_str());
}

void ToolCommandLine::AddChoice(const std::string& name, std::string* field,
                                const std::vector<std::string>& choices, const std::string& help) {
  impl_->description.add_options()(name.c_str(),
                                   po::value<std::string>()
                                       ->default_value(*field, ToText(*field))
                                       ->notifier([name, field, choices](const std::string& value) {
                                         for (const std::string& choice : choices) {
                                           if (value == choice) {
                                             *field = value;
                                             return;
                                           }
                                         }
                                         throw OptionError("--" + name + " must be one of " +
                                                           JoinChoices(choices) + ", not `" +
                                                           value + "`");
                                       }),
                                   ("{" + JoinChoices(choices) + "}. " + help).c_str());
}

void ToolCommandLine::AddRequired(const std::string& name, std::string* field,
                                  const std::string& help) {
  impl_->description.add_options()(name.c_str(), po::value<std::string>(field)->required(),
                                   (help + " Required.").c_str());
}

void ToolCommandLine::AddFlag(const std::string& name, bool* field, bool value_when_given,
                              const std::string& help) {
  impl_->description.add_options()(name.c_str(), help.c_str());
  impl_->flags.emplace_back([name, field, value_when_given](const po::variables_map& vm) {
    if (vm.count(name)) *field = value_when_given;
  });
}

ParseStatus ToolCommandLine::Parse(int argc, const char* const argv[]) const {
  // Help wins over everything else, including unknown options next to it.
  for (int i = 1; i < argc; ++i) {
    if (IsHelpFlag(argv[i])) return ParseStatus::kHelp;
  }
  po::variables_map vm;
  try {
    // No prefix guessing: an abbreviated or misspelt name is reported as
    // unknown instead of silently matching some other option.
    const int style = po::command_line_style::unix_style & ~po::command_line_style::allow_guessing;
    const po::parsed_options parsed =
        po::command_line_parser(argc, argv).options(impl_->description).style(style).run();
    // boost silently drops bare words; the tools take none, so a stray word
    // is almost certainly a value whose option name was mistyped.
    for (const po::option& option : parsed.options) {
      if (option.position_key >= 0) {
        throw OptionError("unexpected argument `" + option.original_tokens.front() +
                          "` (options are --name value; run with --help to list them)");
      }
    }
    po::store(parsed, vm);
    po::notify(vm);
  } catch (const po::unknown_option& e) {
    throw OptionError("unknown option `" + e.get_option_name() +
                      "` (run with --help to list the options)");
  } catch (const po::required_option& e) {
    throw OptionError("missing required option " + e.get_option_name());
  } catch (const po::error& e) {
    throw OptionError(e.what());
  }
  for (const auto& apply : impl_->flags) apply(vm);
  return ParseStatus::kRun;
}

std::string ToolCommandLine::Usage() const {
  std::ostringstream stream;
  stream << impl_->description;
  return stream.str();
}

}  // namespace msp
