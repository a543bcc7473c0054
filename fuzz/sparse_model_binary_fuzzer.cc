// libFuzzer target: cameras.bin, images.bin and points3D.bin.
#include "fuzz/sparse_model_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  msp::fuzz::FuzzSparseModel(data, size, ".bin", &msp::ReadSparseModelBinary);
  return 0;
}
