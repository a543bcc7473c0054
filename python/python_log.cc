#include "python/python_log.h"

#include <pybind11/pybind11.h>

#include <string>

#include "base/log.h"

namespace py = pybind11;

namespace msp {
namespace python {
namespace {

// Python's logging levels.
constexpr int kDebug = 10;
constexpr int kInfo = 20;
constexpr int kWarning = 30;

constexpr char kWarningPrefix[] = "WARNING: ";

int PythonLevel(int log_level, LogSeverity severity) {
  if (severity == LogSeverity::kWarning) return kWarning;
  return log_level >= kLogDetail ? kDebug : kInfo;
}

}  // namespace

// The text of a line not yet complete and the level of its first piece (Logf
// calls build one line piece by piece). The sink is called one piece at a
// time (base/log.h), so it needs no lock of its own.
struct PythonLog::LineBuffer {
  py::object logger;
  std::string partial;
  int level = kInfo;

  void Add(int log_level, LogSeverity severity, const std::string& text) {
    const int piece_level = PythonLevel(log_level, severity);
    if (partial.empty()) level = piece_level;
    partial += text;
    const size_t end = partial.rfind('\n');
    if (end == std::string::npos) return;
    Emit(partial.substr(0, end));
    partial.erase(0, end + 1);
    level = piece_level;
  }

  // One record per non-empty line of `lines`, at `level`.
  void Emit(const std::string& lines) {
    py::gil_scoped_acquire gil;
    size_t begin = 0;
    while (begin <= lines.size()) {
      size_t end = lines.find('\n', begin);
      if (end == std::string::npos) end = lines.size();
      std::string line = lines.substr(begin, end - begin);
      begin = end + 1;
      if (line.empty()) continue;
      // The record's level says it; the prefix is for stdout.
      if (level == kWarning && line.compare(0, sizeof(kWarningPrefix) - 1, kWarningPrefix) == 0) {
        line.erase(0, sizeof(kWarningPrefix) - 1);
      }
      try {
        logger.attr("log")(level, line);
      } catch (py::error_already_set& error) {
        // A failing handler must not end the run, least of all in a worker thread.
        error.discard_as_unraisable("msp_stereo log");
      }
    }
  }
};

PythonLog::PythonLog() : buffer_(std::make_shared<LineBuffer>()) {
  buffer_->logger = py::module_::import("logging").attr("getLogger")(kLoggerName);
  std::shared_ptr<LineBuffer> buffer = buffer_;
  SetLogSink([buffer](int level, LogSeverity severity, const std::string& text) {
    buffer->Add(level, severity, text);
  });
}

PythonLog::~PythonLog() {
  SetLogSink(nullptr);
  if (!buffer_->partial.empty()) buffer_->Emit(buffer_->partial);
}

}  // namespace python
}  // namespace msp
