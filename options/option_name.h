// The name of an option, spelled once: by its field. MSP_OPTION_NAME(o, field)
// is "<Section>.<field>" for a field of PatchMatchStereoOptions or
// MspStereoOptions (their kSection) and "<field>" for a top-level field of
// StereoCommandOptions, e.g. MSP_OPTION_NAME(options.patch_match, window_radius)
// == "PatchMatchStereo.window_radius". The parser registers, Check() reports
// and the start-up print lists options under this name, so a renamed field
// renames its option everywhere and a misspelt field does not compile.
// MSP_OPTION_FLAG is the option as typed on the command line ("--" + name),
// for messages and help texts that tell the user which option to set.
#pragma once

#include <string>
#include <type_traits>
#include <utility>

namespace msp {

// "<section>.<field>", or `field` alone when `section` is empty.
inline std::string OptionName(const char* section, const char* field) {
  const std::string prefix(section);
  return prefix.empty() ? std::string(field) : prefix + "." + field;
}

}  // namespace msp

// `options` is an expression of an options struct (not a pointer); `field` one
// of its fields, which must exist.
#define MSP_OPTION_NAME(options, field)        \
  (static_cast<void>(sizeof((options).field)), \
   ::msp::OptionName(std::decay_t<decltype(options)>::kSection, #field))

// "--" + MSP_OPTION_NAME(options, field), e.g. "--MspStereo.backend".
#define MSP_OPTION_FLAG(options, field) ("--" + MSP_OPTION_NAME(options, field))

// The same for a field of the options struct type `Options`, where no object
// of it is at hand (e.g. a help text that points at an option of another
// struct); the struct is only named, never built.
#define MSP_OPTION_FLAG_OF(Options, field) MSP_OPTION_FLAG(std::declval<Options>(), field)
#define MSP_OPTION_NAME_OF(Options, field) MSP_OPTION_NAME(std::declval<Options>(), field)
