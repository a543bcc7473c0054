// The body of both sparse-model targets: the input is the three files of a
// model, cut at kPartSeparator; the model read is handed to what the
// workspace computes from it first (depth ranges, __auto__ source ranking),
// so a model the reader lets through cannot crash those either.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "io/patch_match_config.h"
#include "io/sparse_model.h"

namespace msp {
namespace fuzz {

inline void FuzzSparseModel(const uint8_t* data, size_t size, const std::string& ext,
                            SparseModel (*read)(const std::string&)) {
  const std::vector<std::string> parts = SplitInput(data, size, 3);
  const std::string dir = InputDir() + "/sparse";
  CreateDirectories(dir);
  const char* names[] = {"cameras", "images", "points3D"};
  for (size_t i = 0; i < 3; ++i) WriteInputFile(std::string("sparse/") + names[i] + ext, parts[i]);
  SparseModel model;
  try {
    model = read(dir);
  } catch (const InputError&) {
    return;
  }
  ComputeDepthRanges(model);
  SelectAutoSourcesBatch(model, std::vector<int>(model.images.size(), 5),
                         /*min_triangulation_angle_deg=*/1.0);
}

}  // namespace fuzz
}  // namespace msp
