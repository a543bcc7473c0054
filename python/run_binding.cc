#include "python/run_binding.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <csignal>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/stereo_command.h"
#include "base/log.h"
#include "base/progress.h"
#include "base/stop_request.h"
#include "options/option_parser.h"
#include "options/stereo_options.h"
#include "python/python_log.h"

namespace py = pybind11;

namespace msp {
namespace python {
namespace {

// One run at a time in a process: the log's sink, the progress listener and
// the stop request are the process's (base/).
std::mutex run_mutex;

bool OnMainThread() {
  const py::module_ threading = py::module_::import("threading");
  return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

// Between two image-passes (ReportProgress's safe point): Python's signal
// handlers run (on the main thread), then the callback, if any, hears
// (done, total, seconds left or None). A KeyboardInterrupt from either stops
// the run as SIGINT does; another exception ends it with that exception.
class ProgressBridge {
 public:
  ProgressBridge(py::object callback, bool main_thread) {
    SetProgressListener([callback, main_thread](const ProgressUpdate& update) {
      py::gil_scoped_acquire gil;
      try {
        if (main_thread && PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (callback.is_none()) return;
        const py::object seconds_left =
            update.seconds_left < 0 ? py::none() : py::cast(update.seconds_left);
        callback(update.done, update.total, seconds_left);
      } catch (py::error_already_set& error) {
        if (error.matches(PyExc_KeyboardInterrupt)) throw StopRequested(SIGINT);
        throw;
      }
    });
  }
  // With the GIL held: the listener holds the callback.
  ~ProgressBridge() { SetProgressListener(nullptr); }
  ProgressBridge(const ProgressBridge&) = delete;
  ProgressBridge& operator=(const ProgressBridge&) = delete;
};

void PatchMatchStereo(const std::filesystem::path& workspace_path,
                      const std::string& workspace_format, const std::string& pmvs_option_name,
                      const std::filesystem::path& config_path,
                      const std::optional<PatchMatchStereoOptions>& options,
                      const std::optional<MspStereoOptions>& msp_options, int random_seed,
                      const py::object& progress) {
  std::unique_lock<std::mutex> lock(run_mutex, std::try_to_lock);
  if (!lock.owns_lock()) {
    throw std::runtime_error(
        "msp_stereo.patch_match_stereo is already running in this process (one run at a time)");
  }
  if (!progress.is_none() && !PyCallable_Check(progress.ptr())) {
    throw py::type_error("progress must be callable as progress(done, total, seconds_left)");
  }
  StereoCommandOptions command;
  command.workspace_path = workspace_path.string();
  command.workspace_format = workspace_format;
  command.pmvs_option_name = pmvs_option_name;
  command.config_path = config_path.string();
  if (options) command.patch_match = *options;
  if (msp_options) command.msp = *msp_options;
  command.random_seed = random_seed;
  ApplySharedOptions(&command);
  // Every line goes to Python's logging, whose levels choose (PythonLog).
  command.log_level = kLogDetail;

  const bool main_thread = OnMainThread();
  PythonLog log;
  ProgressBridge bridge(progress, main_thread);
  // SIGINT is Python's, hence the main thread's: a run there stops on it as
  // msp_stereo does; elsewhere KeyboardInterrupt reaches the main thread as
  // usual and the run goes on.
  std::optional<ScopedStopHandler> stop_handler;
  if (main_thread) {
    stop_handler.emplace();
  } else {
    ClearStopRequest();
  }
  py::gil_scoped_release release;
  RunStereoCommand(command);
}

}  // namespace

void BindPatchMatchStereo(py::module_& module) {
  module.def("patch_match_stereo", &PatchMatchStereo, py::arg("workspace_path"),
             py::arg("workspace_format") = "COLMAP", py::arg("pmvs_option_name") = "option-all",
             py::arg("config_path") = "", py::arg("options") = py::none(),
             py::arg("msp_options") = py::none(), py::kw_only(), py::arg("random_seed") = 0,
             py::arg("progress") = py::none(),
             R"(Dense stereo of a COLMAP workspace, as `msp_stereo --workspace_path ...` (and
pycolmap.patch_match_stereo, whose parameters these are): writes
stereo/{depth,normal}_maps/*.{photometric,geometric}.bin for COLMAP's
stereo_fusion. Images that have their final maps are skipped, so a stopped
run resumes.

options: PatchMatchOptions (--PatchMatchStereo.*), None = the defaults.
msp_options: MspStereoOptions (--MspStereo.*), None = the defaults.
random_seed: the seed of the random numbers (--random_seed); a run is a pure
  function of it.
progress: called after each image-pass as progress(done, total, seconds_left)
  (image-passes done and in all, the estimated seconds left or None).

The log goes to the logging module's logger "msp_stereo" (per-step figures
at DEBUG). Raises OptionError (a ValueError) for an invalid option,
InputError (a RuntimeError) for bad input, naming the file, and
KeyboardInterrupt on Ctrl-C or from `progress`, after the image-pass under
way: nothing is half-written and the same call resumes.)");
}

}  // namespace python
}  // namespace msp
