// libFuzzer target: a workspace image (PNG, JPEG, TIFF or BMP, else refused
// before decoding) of a 16x12 camera (the size of the seed images), read at half
// resolution as msp_stereo reads images/<name>.
#include <cstddef>
#include <cstdint>
#include <string>

#include "base/dense_map.h"
#include "fuzz/fuzz_input.h"
#include "io/errors.h"
#include "io/image_loading.h"

namespace {

constexpr int kWidth = 16;
constexpr int kHeight = 12;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // OpenCV and the header checks tell the format from the bytes, not the name.
  const std::string path = msp::fuzz::WriteInputFile(
      "image.png", std::string(reinterpret_cast<const char*>(data), size));
  msp::DenseMap gray, color;
  try {
    msp::LoadViewImage(path, kWidth, kHeight, kWidth / 2, kHeight / 2, &gray, &color);
  } catch (const msp::InputError&) {
  }
  return 0;
}
