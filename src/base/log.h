// Verbosity of the log, as COLMAP's --log_level (glog's FLAGS_v): a line of
// level n is printed when n <= the log level. Errors, warnings, the start-up
// heading and the end-of-run summary are not subject to it (COLMAP's LOG(INFO)
// and its std::cout output are not either).
#pragma once

namespace msp {

// The lines of the stereo log by level; COLMAP's default --log_level 2 prints
// all of them.
constexpr int kLogProgress = 1;  // one line per image and pass, with the running total
constexpr int kLogDetail = 2;    // the figures of each step (deformable, segment planes, prior)

void SetLogLevel(int level);
int LogLevel();
inline bool LogEnabled(int level) { return level <= LogLevel(); }

// printf to stdout when LogEnabled(level), flushed so a log file shows how far
// a run got when it is killed.
void Logf(int level, const char* format, ...) __attribute__((format(printf, 2, 3)));

}  // namespace msp
