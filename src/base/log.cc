#include "base/log.h"

#include <atomic>
#include <cstdarg>
#include <cstdio>

namespace msp {
namespace {

std::atomic<int> log_level{kLogDetail};

}  // namespace

void SetLogLevel(int level) { log_level = level; }
int LogLevel() { return log_level; }

void Logf(int level, const char* format, ...) {
  if (!LogEnabled(level)) return;
  va_list args;
  va_start(args, format);
  std::vfprintf(stdout, format, args);
  va_end(args);
  std::fflush(stdout);
}

}  // namespace msp
