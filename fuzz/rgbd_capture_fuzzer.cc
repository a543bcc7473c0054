// libFuzzer target: the files of a posed RGB-D capture that msp_import_rgbd
// reads before anything else, cut from one input at the part separator:
// K.txt, poses.txt and one 16-bit depth PNG, for a capture of one 16x12
// image (the size of the seed's depth map).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "tools/rgbd/depth_png.h"
#include "tools/rgbd/rgbd_sequence.h"

namespace {

constexpr int kWidth = 16;
constexpr int kHeight = 12;
constexpr double kUnitsPerMetre = 1000.0;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<std::string> parts = msp::fuzz::SplitInput(data, size, 3);
  msp::rgbd::RgbdPaths paths;
  paths.intrinsics = msp::fuzz::WriteInputFile("K.txt", parts[0]);
  paths.poses = msp::fuzz::WriteInputFile("poses.txt", parts[1]);
  msp::CreateDirectories(msp::JoinPaths(msp::fuzz::InputDir(), "images"));
  msp::CreateDirectories(msp::JoinPaths(msp::fuzz::InputDir(), "depth"));
  msp::fuzz::WriteInputFile("images/a.png", "");
  const std::string depth = msp::fuzz::WriteInputFile("depth/a.png", parts[2]);
  paths.images = msp::JoinPaths(msp::fuzz::InputDir(), "images");
  paths.depth = msp::JoinPaths(msp::fuzz::InputDir(), "depth");
  try {
    msp::rgbd::ReadRgbdSequence(paths);
  } catch (const msp::InputError&) {
  }
  try {
    msp::rgbd::ReadDepthPng(depth, kWidth, kHeight, kUnitsPerMetre);
  } catch (const msp::InputError&) {
  }
  return 0;
}
