// msp_stereo.PatchMatchOptions (pycolmap's name and field names, which are
// COLMAP's) and msp_stereo.MspStereoOptions: the option structs of the
// command, one attribute per option with the help text as its docstring,
// printable, comparable, picklable and checked by the command's Check().
#pragma once

#include <pybind11/pybind11.h>

namespace msp {
namespace python {

void BindOptions(pybind11::module_& module);

}  // namespace python
}  // namespace msp
