// msp_write_gt_maps: copies the ground-truth depth / normal maps into
// <ws>/stereo/ as a method's output (optionally with scaled depth).
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include "integration/scene/gt_maps.h"

namespace {

void PrintUsage() {
  std::printf(
      "Usage: msp_write_gt_maps --workspace <ws> [--ground_truth <ws>/ground_truth]\n"
      "                         [--input_type geometric|photometric] [--scale 1.0]\n");
}

}  // namespace

int main(int argc, char** argv) {
  msp::scene::GroundTruthMapOptions options;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "-h" || arg == "--help") {
        PrintUsage();
        return 0;
      }
      if (i + 1 >= argc) throw std::runtime_error("missing value for " + arg);
      const std::string value = argv[++i];
      if (arg == "--workspace") {
        options.workspace = value;
      } else if (arg == "--ground_truth") {
        options.ground_truth = value;
      } else if (arg == "--input_type") {
        options.input_type = value;
      } else if (arg == "--scale") {
        options.depth_scale = std::stod(value);
      } else {
        throw std::runtime_error("unknown option " + arg);
      }
    }
    const int n = msp::scene::WriteGroundTruthMaps(options);
    std::printf("Wrote %d depth + normal maps (%s, depth x %.4f) to %s/stereo\n", n,
                options.input_type.c_str(), options.depth_scale, options.workspace.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    PrintUsage();
    return 1;
  }
  return 0;
}
