// msp_stereo.patch_match_stereo: pycolmap's patch_match_stereo, on the
// msp_stereo command (app/stereo_command.h), so that the same options
// give the program's maps byte for byte.
#pragma once

#include <pybind11/pybind11.h>

namespace msp {
namespace python {

void BindPatchMatchStereo(pybind11::module_& module);

}  // namespace python
}  // namespace msp
