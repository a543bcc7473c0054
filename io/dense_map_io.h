// COLMAP depth / normal map files (Mat<float>::Read/Write): ASCII header
// "<width>&<height>&<channels>&" then float32 little-endian, channel-planar.
#pragma once

#include <string>

#include "base/dense_map.h"

namespace msp {

// Throws InputError naming the file when it is missing, the header is
// malformed or absurd, or the file size does not match the header.
DenseMap ReadDenseMap(const std::string& path);
// Writes to "<path>.tmp-<pid>" and renames, so a reader never sees half a file.
// Creates missing parent folders. Throws InputError when writing fails, and
// std::logic_error for a NaN/Inf value (COLMAP's fusion would fuse NaN depths
// into garbage points) or a map whose data does not match its size.
void WriteDenseMap(const std::string& path, const DenseMap& map);

}  // namespace msp
