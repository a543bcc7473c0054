// Stopping a run at a safe point on SIGINT / SIGTERM. The handler only sets a
// flag; the work loops (ParallelFor, the pass runner) look at it between
// items and unwind with StopRequested. A file is never cut short: the atomic
// writes run no loop that looks at the flag. A second signal kills at once
// (the handler is reset after the first).
#pragma once

#include <signal.h>

#include <stdexcept>
#include <string>

namespace msp {

class StopRequested : public std::runtime_error {
 public:
  // what() is "stopped by <signal>", or `message` (how far the run got).
  explicit StopRequested(int signal_number);
  StopRequested(int signal_number, const std::string& message);
  int signal_number() const { return signal_number_; }

 private:
  int signal_number_;
};

// Installs the SIGINT / SIGTERM handlers. Also ignores SIGXFSZ, so that a
// write beyond the file size limit (ulimit -f) fails with EFBIG and a message
// naming the file instead of killing the process.
void InstallStopHandlers();

// For a host process with a SIGINT handler of its own (the Python module,
// whose interpreter turns SIGINT into KeyboardInterrupt): while the object
// lives, SIGINT asks the calling thread to stop as InstallStopHandlers's
// handler does; then the host's handler is back. A second SIGINT is the same
// request, never a kill: the process is the host's. Clears a stop request
// left by an earlier run on entry.
class ScopedStopHandler {
 public:
  ScopedStopHandler();
  ~ScopedStopHandler();
  ScopedStopHandler(const ScopedStopHandler&) = delete;
  ScopedStopHandler& operator=(const ScopedStopHandler&) = delete;

 private:
  struct sigaction previous_;  // the host's SIGINT action
};

// The signal that asked to stop, 0 when none.
int PendingStopSignal();

// Throws StopRequested when a stop was asked for and the caller is the thread
// that installed the handlers; other threads only return (their loop ends
// early and the installing thread throws after joining them).
void ThrowIfStopRequested();

// Asks to stop as the handler would (for tests): from any thread; the thread
// that unwinds is the one that installed the handlers.
void RequestStop(int signal_number);
void ClearStopRequest();

// "SIGINT", "SIGTERM" or "signal N".
std::string SignalName(int signal_number);

}  // namespace msp
