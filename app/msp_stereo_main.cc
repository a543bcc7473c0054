// The msp_stereo command: a drop-in replacement for `colmap
// patch_match_stereo` (run as `colmap msp_stereo` through the dispatcher).
// Parses the command line and runs the command (stereo_command.h); the log
// goes to stdout, an error to stderr as one "ERROR: ..." line.

#include <exception>
#include <iostream>

#include "app/stereo_command.h"
#include "base/stop_request.h"
#include "options/option_parser.h"

namespace msp {
namespace {

int Run(int argc, char** argv) {
  StereoCommandOptions options;
  const ParseStatus status = ParseStereoCommand(argc, argv, &options);
  if (status != ParseStatus::kRun) {
    std::cout << StereoCommandUsage(status == ParseStatus::kHelpAll ? UsageScope::kAllOptions
                                                                    : UsageScope::kCommonOptions);
    return 0;
  }
  InstallStopHandlers();
  try {
    RunStereoCommand(options);
  } catch (const StopRequested& stop) {
    // The log has said how far the run got and how to resume it.
    return 128 + stop.signal_number();
  }
  return 0;
}

}  // namespace
}  // namespace msp

int main(int argc, char** argv) {
  try {
    return msp::Run(argc, argv);
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "ERROR: " << e.what() << std::endl;
    return 1;
  }
}
