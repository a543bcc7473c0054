// What the fuzz targets share: the readers under test take file paths, so
// each input is written to a file in a folder private to the fuzzing process
// (under $TMPDIR, removed at exit), and inputs that stand for several files
// (a sparse model) are cut into parts at a separator line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace msp {
namespace fuzz {

// Separates the files of a multi-file input ("cameras<sep>images<sep>points3D").
// A line of its own, so a text seed stays readable.
constexpr char kPartSeparator[] = "\n%%msp-fuzz-part%%\n";

// The folder of this process's input files; created on the first call.
const std::string& InputDir();

// Writes `bytes` to InputDir()/<name> and returns the path.
std::string WriteInputFile(const std::string& name, const std::string& bytes);

// The input cut at the separators into exactly `count` parts: missing parts
// are empty, and the last part keeps any further separators.
std::vector<std::string> SplitInput(const uint8_t* data, size_t size, size_t count);

}  // namespace fuzz
}  // namespace msp
