// msp_write_gt_maps: copies the ground-truth depth / normal maps into
// <ws>/stereo/ as a method's output (optionally with scaled depth).
#include <cstdio>
#include <exception>
#include <iostream>

#include "options/tool_command_line.h"
#include "tools/scene/gt_maps.h"

int main(int argc, char** argv) {
  msp::scene::GroundTruthMapOptions options;
  msp::ToolCommandLine command_line(
      "Usage: msp_write_gt_maps --workspace <ws> [options]",
      "Writes the ground-truth depth and normal maps of msp_make_scene to\n"
      "<ws>/stereo/{depth,normal}_maps as if a method had produced them.");
  command_line.AddRequired("workspace", &options.workspace, "Workspace written by msp_make_scene.");
  command_line.Add("ground_truth", &options.ground_truth, "Ground truth folder.",
                   "<workspace>/ground_truth");
  command_line.AddChoice("input_type", &options.input_type, {"geometric", "photometric"},
                         "Suffix of the written maps (<image>.<input_type>.bin).");
  command_line.Add("scale", &options.depth_scale,
                   "Factor applied to every depth (> 0); 1 = the exact ground truth.");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    const int n = msp::scene::WriteGroundTruthMaps(options);
    std::printf("Wrote %d depth + normal maps (%s, depth x %.4f) to %s/stereo\n", n,
                options.input_type.c_str(), options.depth_scale, options.workspace.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
  return 0;
}
