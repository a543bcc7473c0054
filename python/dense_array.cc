#include "python/dense_array.h"

#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <vector>

#include "base/dense_map.h"
#include "io/dense_map_io.h"

namespace py = pybind11;

namespace msp {
namespace python {
namespace {

// height x width for one channel (a depth map), height x width x channels
// else (a normal map), C-contiguous; the file holds the channels one plane
// after the other.
py::array_t<float> ReadArray(const std::filesystem::path& path) {
  const DenseMap map = ReadDenseMap(path.string());
  std::vector<py::ssize_t> shape = {map.height, map.width};
  if (map.channels > 1) shape.push_back(map.channels);
  py::array_t<float> array(shape);
  float* out = array.mutable_data();
  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      for (int c = 0; c < map.channels; ++c) *out++ = map.At(row, col, c);
    }
  }
  return array;
}

}  // namespace

void BindDenseArray(py::module_& module) {
  module.def("read_array", &ReadArray, py::arg("path"),
             "A depth map (height x width) or normal map (height x width x 3) of "
             "stereo/{depth,normal}_maps as a float32 numpy array, as COLMAP's "
             "read_write_dense.py reads it (0 = no depth). Raises InputError naming the file when "
             "it is missing or not such a map.");
}

}  // namespace python
}  // namespace msp
