// libFuzzer target: cameras.txt, images.txt and points3D.txt.
#include "fuzz/sparse_model_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  msp::fuzz::FuzzSparseModel(data, size, ".txt", &msp::ReadSparseModelText);
  return 0;
}
