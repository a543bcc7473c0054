// libFuzzer target: a depth or normal map file (COLMAP's Mat<float> .bin).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_input.h"
#include "io/dense_map_io.h"
#include "io/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      msp::fuzz::WriteInputFile("map.bin", std::string(reinterpret_cast<const char*>(data), size));
  try {
    msp::ReadDenseMap(path);
  } catch (const msp::InputError&) {
  }
  return 0;
}
