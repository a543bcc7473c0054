#include "base/log.h"

#include <atomic>
#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <utility>

#include "base/string_printf.h"

namespace msp {
namespace {

std::atomic<int> log_level{kLogDetail};

// One call of the sink at a time: lines of worker threads never interleave.
std::mutex sink_mutex;
LogSink sink;  // empty = stdout

void Write(int level, LogSeverity severity, const std::string& text) {
  std::lock_guard<std::mutex> lock(sink_mutex);
  if (sink) {
    sink(level, severity, text);
    return;
  }
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fflush(stdout);
}

}  // namespace

void SetLogLevel(int level) { log_level = level; }
int LogLevel() { return log_level; }

void SetLogSink(LogSink new_sink) {
  std::lock_guard<std::mutex> lock(sink_mutex);
  sink = std::move(new_sink);
}

void LogText(int level, const std::string& text) {
  if (LogEnabled(level) && !text.empty()) Write(level, LogSeverity::kInfo, text);
}

void Logf(int level, const char* format, ...) {
  if (!LogEnabled(level)) return;
  va_list args;
  va_start(args, format);
  const std::string text = StringPrintfV(format, args);
  va_end(args);
  LogText(level, text);
}

void LogWarning(const std::string& message) {
  Write(kLogAlways, LogSeverity::kWarning, "WARNING: " + message + "\n");
}

}  // namespace msp
