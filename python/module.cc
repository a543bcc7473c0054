// The msp_stereo Python module: pycolmap's patch_match_stereo on this
// project's stereo, its option classes and read_array; the errors of the
// command as Python exceptions with the command's messages.

#include <pybind11/pybind11.h>

#include "base/stop_request.h"
#include "io/errors.h"
#include "options/option_parser.h"
#include "python/dense_array.h"
#include "python/options_binding.h"
#include "python/python_log.h"
#include "python/run_binding.h"

namespace py = pybind11;

PYBIND11_MODULE(msp_stereo, module) {
  module.doc() =
      "Dense stereo for COLMAP workspaces (MSP-MVS), shaped like pycolmap: "
      "patch_match_stereo(workspace_path, ..., options=PatchMatchOptions(), "
      "msp_options=MspStereoOptions()), then COLMAP's stereo_fusion.";
  module.attr("__version__") = MSP_VERSION;
  module.attr("LOGGER_NAME") = msp::python::kLoggerName;

  // What the command prints as "ERROR: <message>" is the exception's message.
  static py::exception<msp::OptionError> option_error(module, "OptionError", PyExc_ValueError);
  static py::exception<msp::InputError> input_error(module, "InputError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const msp::OptionError& e) {
      option_error(e.what());
    } catch (const msp::InputError& e) {
      input_error(e.what());
    } catch (const msp::StopRequested& e) {
      // The command exits with 128 + SIGINT; Python's way is KeyboardInterrupt.
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });

  msp::python::BindOptions(module);
  msp::python::BindPatchMatchStereo(module);
  msp::python::BindDenseArray(module);
}
