// libFuzzer target: a mask layer PNG of the segmentation prior, read for a
// 16x12 image (the size of the seed layers) at half resolution.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_input.h"
#include "io/errors.h"
#include "io/mask_layers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  msp::fuzz::WriteInputFile("image.png.0.png",
                            std::string(reinterpret_cast<const char*>(data), size));
  msp::MaskImage image;
  image.name = "image.png";
  image.width = 16;
  image.height = 12;
  image.work_width = 8;
  image.work_height = 6;
  try {
    msp::ReadMaskLayers(msp::fuzz::InputDir(), image, /*num_levels=*/1);
  } catch (const msp::InputError&) {
  }
  return 0;
}
