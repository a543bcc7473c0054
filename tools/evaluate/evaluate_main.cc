// msp_evaluate: depth/normal maps and a fused point cloud against the ground
// truth of msp_make_scene.
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "options/tool_command_line.h"
#include "tools/evaluate/evaluate_report.h"
#include "tools/evaluate/evaluate_workspace.h"

int main(int argc, char** argv) {
  msp::eval::EvaluationOptions options;
  std::string json_path;
  msp::ToolCommandLine command_line(
      "Usage: msp_evaluate --workspace <ws> [options]",
      "Evaluates the depth maps of <ws>/stereo and a fused point cloud against the\n"
      "ground truth of msp_make_scene: per-map figures, and the cloud's accuracy,\n"
      "completeness and F1.");
  command_line.AddRequired("workspace", &options.workspace,
                           "Workspace written by msp_make_scene, with the method's maps.");
  command_line.Add("ground_truth", &options.ground_truth, "Ground truth folder.",
                   "<workspace>/ground_truth");
  command_line.AddChoice("input_type", &options.input_type, {"geometric", "photometric"},
                         "Which maps to evaluate (<image>.<input_type>.bin).");
  command_line.Add("fused", &options.fused, "Fused point cloud (.ply) to evaluate; \"\" = none.");
  command_line.AddFlag("no_maps", &options.evaluate_maps, /*value_when_given=*/false,
                       "Skip the depth maps; evaluate the fused cloud only.");
  command_line.Add("json", &json_path, "Also write the figures to this JSON file; \"\" = none.");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    const msp::eval::EvaluationResult result = msp::eval::EvaluateWorkspace(options);
    msp::eval::PrintReport(result, std::cout);
    if (!json_path.empty()) {
      std::ofstream file(json_path);
      file << msp::eval::ReportJson(result);
      if (!file) throw std::runtime_error("cannot write " + json_path);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
  return 0;
}
