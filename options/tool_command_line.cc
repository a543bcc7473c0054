#include "options/tool_command_line.h"

#include <boost/program_options.hpp>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "options/command_line_common.h"

namespace msp {
namespace {

namespace po = boost::program_options;

using command_line::DefaultText;

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

}  // namespace

struct ToolCommandLine::Impl {
  po::options_description description;
  // Applied after parsing: the value-less flags, which boost stores no value for.
  std::vector<std::function<void(const po::variables_map&)>> flags;
  // The options that bare words fill, in order.
  std::vector<std::string> positional;

  explicit Impl(const std::string& caption)
      : description(caption, command_line::kHelpLineLength,
                    command_line::kHelpMinDescriptionLength) {}
};

ToolCommandLine::ToolCommandLine(const std::string& usage, const std::string& summary)
    : impl_(std::make_unique<Impl>(usage + "\n\n" + summary + "\n\nOptions")) {
  command_line::AddHelpOption(&impl_->description);
}

ToolCommandLine::~ToolCommandLine() = default;

void ToolCommandLine::Add(const std::string& name, std::string* field, const std::string& help,
                          const std::string& default_text) {
  impl_->description.add_options()(
      name.c_str(),
      po::value<std::string>(field)->default_value(
          *field, default_text.empty() ? DefaultText(*field) : default_text),
      help.c_str());
}

void ToolCommandLine::Add(const std::string& name, int* field, const std::string& help) {
  impl_->description.add_options()(
      name.c_str(), po::value<int>(field)->default_value(*field, DefaultText(*field)),
      help.c_str());
}

void ToolCommandLine::Add(const std::string& name, double* field, const std::string& help) {
  impl_->description.add_options()(
      name.c_str(), po::value<double>(field)->default_value(*field, DefaultText(*field)),
      help.c_str());
}

void ToolCommandLine::Add(const std::string& name, uint64_t* field, const std::string& help) {
  // boost converts "-1" to an unsigned type by wrapping it; read the text and
  // convert it here instead.
  impl_->description.add_options()(name.c_str(),
                                   po::value<std::string>()
                                       ->default_value(DefaultText(*field))
                                       ->notifier([name, field](const std::string& text) {
                                         *field = ParseUnsigned(name, text);
                                       }),
                                   help.c_str());
}

void ToolCommandLine::AddChoice(const std::string& name, std::string* field,
                                const std::vector<std::string>& choices, const std::string& help) {
  impl_->description.add_options()(name.c_str(),
                                   po::value<std::string>()
                                       ->default_value(*field, DefaultText(*field))
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

void ToolCommandLine::SetPositional(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const po::option_description* option = impl_->description.find_nothrow(name, /*approx=*/false);
    if (option == nullptr || option->semantic()->max_tokens() == 0) {
      throw std::invalid_argument("ToolCommandLine: positional option --" + name +
                                  " is not a declared option with a value");
    }
  }
  impl_->positional = names;
}

ParseStatus ToolCommandLine::Parse(int argc, const char* const argv[]) const {
  if (command_line::HasHelpFlag(argc, argv)) return ParseStatus::kHelp;
  po::variables_map vm;
  command_line::StoreCommandLine(argc, argv, impl_->description, impl_->positional, &vm);
  command_line::NotifyOptions(&vm);
  for (const auto& apply : impl_->flags) apply(vm);
  return ParseStatus::kRun;
}

std::string ToolCommandLine::Usage() const {
  std::ostringstream stream;
  stream << impl_->description;
  return stream.str();
}

}  // namespace msp
