// msp_import_rgbd: a posed RGB-D capture (images, 16-bit depth PNGs, K,
// camera-to-world poses) as a COLMAP dense workspace with its sensor depth as
// ground truth for msp_evaluate (tools/rgbd/import_rgbd.h).
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include "options/tool_command_line.h"
#include "tools/rgbd/import_rgbd.h"

int main(int argc, char** argv) {
  msp::rgbd::ImportOptions o;
  msp::ToolCommandLine command_line(
      "Usage: msp_import_rgbd --input <dir> --output <ws> --depth_units_per_metre <u> [options]",
      "Makes a COLMAP dense workspace from a posed RGB-D sequence: the poses held fixed,\n"
      "SIFT tracks triangulated by COLMAP (feature_extractor, exhaustive_matcher,\n"
      "point_triangulator), image_undistorter, and the sensor depth as ground truth in\n"
      "<ws>/ground_truth for msp_evaluate.");
  command_line.Add("input", &o.input,
                   "Folder with images/, depth/, K.txt and poses.txt (each may be given on its own "
                   "below).");
  command_line.Add("images", &o.paths.images, "Colour images (.png, .jpg), sorted by name.",
                   "<input>/images");
  command_line.Add("depth", &o.paths.depth,
                   "16-bit depth PNGs (0 = no measurement), paired with the images in sorted "
                   "order, registered to them pixel for pixel.",
                   "<input>/depth");
  command_line.Add("intrinsics", &o.paths.intrinsics,
                   "Row-major 3x3 K: one for every frame, or one per frame.", "<input>/K.txt");
  command_line.Add("poses", &o.paths.poses,
                   "A row-major 4x4 camera-to-world pose per line (metres), in image order.",
                   "<input>/poses.txt");
  command_line.AddRequired("output", &o.output, "Workspace folder to write (must not exist).");
  command_line.Add("depth_units_per_metre", &o.depth_units_per_metre,
                   "Depth PNG units per metre (required): 1000 = millimetres, 5000 = TUM RGB-D.");
  command_line.Add("pixel_centre_offset", &o.pixel_centre_offset,
                   "Added to K's cx, cy for COLMAP, whose pixel (0, 0) is centred at (0.5, 0.5): "
                   "0.5 when K centres pixels on integers (OpenCV, most datasets), 0 when K is "
                   "already COLMAP's.");
  command_line.Add("frames", &o.selection.frames,
                   "Frame index ranges in sorted order, e.g. 0-8,35-39; \"\" = all.");
  command_line.Add("step", &o.selection.step, "Every step-th frame of each range.");
  command_line.Add("min_baseline", &o.selection.min_baseline,
                   "Skip a frame closer than this (metres) to the last one kept.");
  command_line.Add("colmap", &o.colmap, "The COLMAP binary.");
  command_line.Add("num_threads", &o.num_threads,
                   "Threads of COLMAP's SIFT extraction and matching; -1 = all cores.");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    const auto start = std::chrono::steady_clock::now();
    const msp::rgbd::ImportSummary s = msp::rgbd::ImportRgbd(o);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string frames;
    for (const int i : s.frames) frames += (frames.empty() ? "" : " ") + std::to_string(i);
    std::printf(
        "Wrote %s: %zu frames (%s), %d points3D (mean track length %.2f, reprojection error "
        "%.2f px), %d surface samples, %.1f %% of the pixels measured, extent %.3f m, %.1f s\n",
        o.output.c_str(), s.frames.size(), frames.c_str(), s.num_points3D, s.mean_track_length,
        s.mean_reprojection_error, s.num_surface_samples, 100.0 * s.measured_fraction, s.extent,
        seconds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
  return 0;
}
