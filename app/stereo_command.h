// The msp_stereo command without its command line: checks the options, reads
// the COLMAP dense workspace, runs the stereo back-end and writes
// stereo/{depth,normal}_maps the way COLMAP's stereo_fusion expects them.
// The msp_stereo program and the Python module both call it, so the same
// options give byte-identical maps either way.
#pragma once

#include "options/stereo_options.h"

namespace msp {

// Runs the command with `options`, first checked by CheckStereoCommandOptions
// (option_check.h) as the program checks them. The log goes through
// base/log.h at options.log_level. Throws OptionError for an invalid option,
// InputError for bad input (naming the file), std::runtime_error when the
// back-end cannot run, and StopRequested when a stop was asked for
// (base/stop_request.h), whose what() is the line the log ends with: how far
// the run got and that the same call resumes it. Stop handlers are the
// caller's to install.
void RunStereoCommand(const StereoCommandOptions& options);

}  // namespace msp
