// msp_evaluate: depth/normal maps and a fused point cloud against the ground
// truth of msp_make_scene.
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "tools/evaluate_report.h"
#include "tools/evaluate_workspace.h"

namespace {

void PrintUsage() {
  std::printf(
      "Usage: msp_evaluate --workspace <ws> [--ground_truth <ws>/ground_truth]\n"
      "                    [--input_type geometric|photometric] [--fused <ws>/fused.ply]\n"
      "                    [--no_maps] [--json out.json]\n");
}

}  // namespace

int main(int argc, char** argv) {
  msp::eval::EvaluationOptions options;
  std::string json_path;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "-h" || arg == "--help") {
        PrintUsage();
        return 0;
      }
      if (arg == "--no_maps") {
        options.evaluate_maps = false;
        continue;
      }
      if (i + 1 >= argc) throw std::runtime_error("missing value for " + arg);
      const std::string value = argv[++i];
      if (arg == "--workspace") {
        options.workspace = value;
      } else if (arg == "--ground_truth") {
        options.ground_truth = value;
      } else if (arg == "--input_type") {
        if (value != "geometric" && value != "photometric") {
          throw std::runtime_error("--input_type must be geometric or photometric, not " + value);
        }
        options.input_type = value;
      } else if (arg == "--fused") {
        options.fused = value;
      } else if (arg == "--json") {
        json_path = value;
      } else {
        throw std::runtime_error("unknown option " + arg);
      }
    }
    if (options.workspace.empty()) throw std::runtime_error("--workspace is required");
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
