// The stereo log: verbosity as COLMAP's --log_level (glog's FLAGS_v), and
// where the lines go. A line of level n is printed when n <= the log level.
// Errors, warnings, the start-up heading and the end-of-run summary are not
// subject to it (COLMAP's LOG(INFO) and its std::cout output are not either).
//
// Everything the library says goes through one sink: stdout for the command
// (README: the log goes to stdout, errors to stderr), Python's logging for
// the Python module. Errors are exceptions, never log lines.
#pragma once

#include <functional>
#include <sstream>
#include <string>

namespace msp {

// The lines of the stereo log by level; COLMAP's default --log_level 2 prints
// all of them.
constexpr int kLogAlways = 0;    // the start, the summary: whatever the log level
constexpr int kLogProgress = 1;  // one line per image and pass, with the running total
constexpr int kLogDetail = 2;    // the figures of each step (deformable, segment planes, prior)

void SetLogLevel(int level);
int LogLevel();
inline bool LogEnabled(int level) { return level <= LogLevel(); }

enum class LogSeverity { kInfo, kWarning };

// Receives the log's text as it is written: part of a line (Logf calls that
// build one line piece by piece), a line or several, each ending in '\n'.
// `level` is the text's verbosity level (kLogAlways for warnings).
using LogSink = std::function<void(int level, LogSeverity severity, const std::string& text)>;

// Replaces the sink; an empty one restores stdout. Set it while nothing logs
// (before or after a run): the sink itself is called from whichever thread
// logs, one call at a time.
void SetLogSink(LogSink sink);

// Writes `text` through the sink when LogEnabled(level); stdout is flushed
// after each call, so a log file shows how far a run got when it is killed.
void LogText(int level, const std::string& text);

// printf through LogText.
void Logf(int level, const char* format, ...) __attribute__((format(printf, 2, 3)));

// "WARNING: <message>\n", whatever the log level.
void LogWarning(const std::string& message);

// A piece of log built with <<, written through LogText when it goes out of
// scope: LogStream() << "Reading " << path << "\n";
class LogStream {
 public:
  explicit LogStream(int level = kLogAlways) : level_(level) {}
  ~LogStream() { LogText(level_, stream_.str()); }
  LogStream(const LogStream&) = delete;
  LogStream& operator=(const LogStream&) = delete;

  template <typename T>
  LogStream& operator<<(const T& value) {
    stream_ << value;
    return *this;
  }
  // Manipulators such as std::fixed.
  LogStream& operator<<(std::ios_base& (*manipulator)(std::ios_base&)) {
    stream_ << manipulator;
    return *this;
  }

 private:
  int level_;
  std::ostringstream stream_;
};

}  // namespace msp
