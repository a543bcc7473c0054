// msp_make_scene: writes the bundled test scene as a COLMAP dense workspace
// with exact ground truth (see tools/scene/scene.h for the scene).
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>

#include "options/tool_command_line.h"
#include "tools/scene/generate.h"

int main(int argc, char** argv) {
  msp::scene::GeneratorOptions options;
  msp::ToolCommandLine command_line(
      "Usage: msp_make_scene --output <dir> [options]",
      "Renders the bundled scene as a COLMAP dense workspace: images/, sparse/,\n"
      "stereo/*.cfg, run-colmap-*.sh and the exact ground truth in ground_truth/\n"
      "(with --ideal_masks also the ideal mask layers in masks/).");
  command_line.AddRequired("output", &options.output, "Workspace folder to write (created).");
  command_line.Add(
      "seed", &options.seed,
      "Seed of the scene's random draws (camera jitter, rendering, sparse tracks); the "
      "scene is a pure function of it.");
  command_line.Add("width", &options.rig.width, "Image width in pixels.");
  command_line.Add("height", &options.rig.height, "Image height in pixels.");
  command_line.Add("num_cameras", &options.rig.num_cameras, "Number of views on the camera arc.");
  command_line.Add("num_points", &options.num_points,
                   "Target number of sparse points (3D points with tracks) of the model.");
  command_line.AddChoice("kind", &options.kind, {"room", "street"},
                         "The scene: room (the bundled scene: a room with a window to the sky) or "
                         "street (facades, a tower and a tree under open sky that reaches the top "
                         "and side borders of every view).");
  command_line.AddChoice("sky", &options.sky, {"", "pale", "blue", "overcast", "clouds"},
                         "The sky: pale (the bundled scene's), blue (a deeper gradient), overcast "
                         "(white-grey) or clouds (blue with soft white clouds); empty: the "
                         "kind's own (room: pale, street: blue). Its ground truth is empty.");
  command_line.AddFlag("no_sky_window", &options.sky_window, false,
                       "Close the window to open sky in the y = 0 wall (whose pixels have nothing "
                       "to reconstruct: their ground truth is empty).");
  command_line.AddFlag(
      "ideal_masks", &options.ideal_masks, true,
      "Also write ideal segmentation masks to <output>/masks/<image>.<level>.png: the "
      "renderer's surface ids at each pixel's centre ray, level 0 objects, 1 faces, 2 faces "
      "split by paint (16-bit, 0 = sky), the layout msp_stereo reads as mask layers. The "
      "ceiling of what a segmenter can give the prior (docs/segmentation_masks.md). Images and "
      "ground truth are the same with or without it.");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
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
    return 1;
  }
  return 0;
}
