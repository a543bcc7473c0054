// libFuzzer target: stereo/patch-match.cfg.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_input.h"
#include "io/errors.h"
#include "io/patch_match_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = msp::fuzz::WriteInputFile(
      "patch-match.cfg", std::string(reinterpret_cast<const char*>(data), size));
  try {
    msp::ParsePatchMatchConfig(path);
  } catch (const msp::InputError&) {
  }
  return 0;
}
