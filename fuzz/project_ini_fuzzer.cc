// libFuzzer target: the --project_path ini file of msp_stereo, parsed as the
// command reads it (command line first, then the ini) and then checked.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_input.h"
#include "options/option_check.h"
#include "options/option_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = msp::fuzz::WriteInputFile(
      "project.ini", std::string(reinterpret_cast<const char*>(data), size));
  // The command line names a workspace, so an ini without one still reaches
  // the option checks.
  const char* argv[] = {"msp_stereo", "--workspace_path", "workspace", "--project_path",
                        path.c_str()};
  msp::StereoCommandOptions options;
  try {
    msp::ParseStereoCommand(5, argv, &options);
    msp::CheckStereoCommandOptions(options);
  } catch (const msp::OptionError&) {
  }
  return 0;
}
