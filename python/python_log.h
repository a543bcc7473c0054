// The stereo log (base/log.h) into Python's logging, logger "msp_stereo",
// one record per line: warnings at WARNING, the per-step figures (kLogDetail)
// at DEBUG, the rest at INFO. Python's logging decides what is shown.
#pragma once

#include <memory>

namespace msp {
namespace python {

// The logger's name.
constexpr char kLoggerName[] = "msp_stereo";

// Sends the log to Python's logging while it lives. Made and destroyed with
// the GIL held; in between, the lines of any thread take the GIL one line at
// a time.
class PythonLog {
 public:
  PythonLog();
  // Logs a last line that has no '\n', and gives the log back to stdout.
  ~PythonLog();
  PythonLog(const PythonLog&) = delete;
  PythonLog& operator=(const PythonLog&) = delete;

 private:
  struct LineBuffer;
  std::shared_ptr<LineBuffer> buffer_;  // shared with the sink
};

}  // namespace python
}  // namespace msp
