// Running the real binaries from the integration tests: which COLMAP, and a
// command with its output in a log file.
#pragma once

#include <cstdlib>
#include <string>

namespace msp {
namespace test {

// $MSP_REAL_COLMAP (ctest sets it from the build's MSP_REAL_COLMAP), else
// Debian's /usr/bin/colmap.
inline std::string RealColmap() {
  const char* env = std::getenv("MSP_REAL_COLMAP");
  return env != nullptr ? env : "/usr/bin/colmap";
}

// Runs `command` through the shell with stdout and stderr in `log`; returns
// std::system's status (0 = exit code 0).
inline int RunLogged(const std::string& command, const std::string& log) {
  return std::system((command + " > " + log + " 2>&1").c_str());
}

}  // namespace test
}  // namespace msp
