// Runs an external program (the real `colmap`) with its output in a log file.
#pragma once

#include <string>
#include <vector>

namespace msp {
namespace rgbd {

// Runs argv[0] (looked up on PATH when it has no '/') with the arguments,
// stdout and stderr appended to `log_path`, and waits. Returns its exit code,
// 128 + the signal number when a signal ended it, or -1 when it could not be
// started.
int RunCommand(const std::vector<std::string>& argv, const std::string& log_path);

// Runs the command and throws InputError naming it, its exit code, the log
// and the log's last line when it does not exit with 0.
void RunCommandOrThrow(const std::vector<std::string>& argv, const std::string& log_path);

}  // namespace rgbd
}  // namespace msp
