// msp_make_scene: writes the bundled test scene as a COLMAP dense workspace
// with exact ground truth (see integration/scene/scene.h for the scene).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

#include "integration/scene/generate.h"

namespace {

void PrintUsage() {
  std::printf(
      "Usage: msp_make_scene --output <dir> [--seed N] [--width 640] [--height 480]\n"
      "                      [--num_cameras 10]\n"
      "Writes images/, sparse/, stereo/*.cfg, run-colmap-*.sh and ground_truth/.\n");
}

}  // namespace

int main(int argc, char** argv) {
  msp::scene::GeneratorOptions options;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "-h" || arg == "--help") {
        PrintUsage();
        return 0;
      }
      if (i + 1 >= argc) throw std::runtime_error("missing value for " + arg);
      const std::string value = argv[++i];
      if (arg == "--output") {
        options.output = value;
      } else if (arg == "--seed") {
        options.seed = std::stoull(value);
      } else if (arg == "--width") {
        options.rig.width = std::stoi(value);
      } else if (arg == "--height") {
        options.rig.height = std::stoi(value);
      } else if (arg == "--num_cameras") {
        options.rig.num_cameras = std::stoi(value);
      } else {
        throw std::runtime_error("unknown option " + arg);
      }
    }
    const auto start = std::chrono::steady_clock::now();
    const msp::scene::GeneratorSummary s = msp::scene::GenerateScene(options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "Wrote %s: %d images, %d points3D (mean track length %.2f), %d surface samples, "
        "extent %.3f m, %.1f s\n",
        options.output.c_str(), s.num_images, s.num_points3D, s.mean_track_length,
        s.num_surface_samples, s.extent, seconds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    PrintUsage();
    return 1;
  }
  return 0;
}
