// msp_stereo.read_array: a COLMAP depth or normal map (.bin) as a numpy
// array, as COLMAP's scripts/python/read_write_dense.py reads it.
#pragma once

#include <pybind11/pybind11.h>

namespace msp {
namespace python {

void BindDenseArray(pybind11::module_& module);

}  // namespace python
}  // namespace msp
