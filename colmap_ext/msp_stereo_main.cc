// The msp_stereo command: a drop-in replacement for `colmap
// patch_match_stereo` (run as `colmap msp_stereo` through the dispatcher).
// Reads a COLMAP dense workspace, runs the stereo back-end and writes
// stereo/{depth,normal}_maps the way COLMAP's stereo_fusion expects them.

#include <chrono>
#include <exception>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "colmap_ext/map_writer.h"
#include "colmap_ext/workspace.h"
#include "options/option_check.h"
#include "options/option_parser.h"
#include "stereo.h"

namespace msp {
namespace {

// Per-run scratch space (spilled per-image state), inside the workspace so
// it lives on the same disk as the maps.
constexpr char kScratchSubdir[] = "/stereo/msp";

void PrintHeading(const std::string& heading) {
  const std::string rule(78, '=');
  std::cout << "\n" << rule << "\n" << heading << "\n" << rule << "\n\n";
}

// Options accepted for COLMAP compatibility that this build does not honour;
// said once at start-up so nobody wonders why they had no effect.
void WarnAboutIgnoredOptions(const StereoCommandOptions& options) {
  if (options.patch_match.write_consistency_graph) {
    std::cout << "WARNING: --PatchMatchStereo.write_consistency_graph is ignored: no "
                 "consistency graphs are written (no COLMAP command reads them)\n";
  }
  const PatchMatchStereoOptions defaults;
  if (options.patch_match.window_step != defaults.window_step) {
    std::cout << "WARNING: --PatchMatchStereo.window_step is ignored (the window sampling "
                 "step is --MspStereo.window_step)\n";
  }
  if (!options.msp.bilateral_ncc && (options.patch_match.sigma_spatial != defaults.sigma_spatial ||
                                     options.patch_match.sigma_color != defaults.sigma_color)) {
    std::cout << "WARNING: --PatchMatchStereo.sigma_spatial / sigma_color only apply with "
                 "--MspStereo.bilateral_ncc true\n";
  }
  if (options.patch_match.num_iterations != defaults.num_iterations) {
    std::cout << "WARNING: --PatchMatchStereo.num_iterations is ignored (the APD schedule runs "
                 "3 red-black iterations per pass, 4 passes per round)\n";
  }
  if (options.patch_match.ncc_sigma != defaults.ncc_sigma ||
      options.patch_match.incident_angle_sigma != defaults.incident_angle_sigma) {
    std::cout << "WARNING: --PatchMatchStereo.ncc_sigma / incident_angle_sigma are ignored "
                 "(view selection follows ACMM, not COLMAP's likelihood model)\n";
  }
  if (options.msp.segmentation_prior && !options.msp.deformable) {
    std::cout << "WARNING: --MspStereo.segmentation_prior has no effect without "
                 "--MspStereo.deformable (the prior confines the anchors of deformable patches)\n";
  }
  if (options.msp.write_previews && !(options.msp.segmentation_prior && options.msp.deformable)) {
    std::cout << "WARNING: --MspStereo.write_previews writes nothing: the segmentation prior "
                 "does not run\n";
  }
  if (options.msp.backend == "cpu" && options.patch_match.gpu_index != "-1") {
    std::cout << "WARNING: --PatchMatchStereo.gpu_index is ignored by the cpu back-end\n";
  }
}

int Run(int argc, char** argv) {
  StereoCommandOptions options;
  if (ParseStereoCommand(argc, argv, &options) == ParseStatus::kHelp) {
    std::cout << StereoCommandUsage();
    return 0;
  }
  CheckStereoCommandOptions(options);

  const auto start = std::chrono::steady_clock::now();
  PrintHeading("MSP stereo (backend: " + options.msp.backend + ")");
  std::cout << "Options:\n";
  PrintStereoCommandOptions(options, std::cout);
  std::cout << std::endl;
  WarnAboutIgnoredOptions(options);

  std::cout << "Reading workspace " << options.workspace_path << "..." << std::endl;
  const Workspace workspace = LoadWorkspace(options);
  std::cout << "  " << workspace.views.size() << " images, " << workspace.problems.size()
            << " problems" << std::endl;
  WriteFusionConfigIfMissing(workspace);

  std::vector<std::string> names;
  names.reserve(workspace.views.size());
  for (const View& view : workspace.views) names.push_back(view.name);
  MapWriter writer(workspace.path, std::move(names), options.patch_match.geom_consistency);

  RunStereo(workspace.views, workspace.problems, options.patch_match, options.msp,
            workspace.path + kScratchSubdir, writer);

  const double minutes =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;
  std::cout << "Elapsed time: " << std::fixed << std::setprecision(3) << minutes << " [minutes]"
            << std::endl;
  return 0;
}

}  // namespace
}  // namespace msp

int main(int argc, char** argv) {
  try {
    return msp::Run(argc, argv);
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "ERROR: " << e.what() << std::endl;
    return 1;
  }
}
