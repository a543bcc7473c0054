// The device self-check's steps (src/backend/device_self_check.h) on this
// build's CPU core, so that two builds of the core can be compared step by
// step as the self-check compares a GPU with the CPU:
//
//   msp_core_steps --write DIR     runs every step, each from the one before,
//                                  and writes each step's start and result
//   msp_core_steps --compare DIR   runs every step from DIR's start and prints
//                                  the share of pixels differing from DIR's
//                                  result; exit 1 when a step differs at more
//                                  than the self-check's bound
//
// tests/scalar_vs_vector.sh writes with the native build (AVX2 + FMA) and
// compares with the scalar build, whose arithmetic is the GPU kernels'.
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/cpu/cpu_sweep_engine.h"
#include "backend/device_self_check.h"
#include "backend/self_check_problem.h"
#include "engine/sweep_engine.h"
#include "options/tool_command_line.h"
#include "patch_match/pixel_state_io.h"

namespace msp {
namespace {

// One thread: the problem is small, and the results do not depend on it.
constexpr int kNumThreads = 1;

std::string StepFile(const std::string& dir, int step, const char* what) {
  return dir + "/step_" + std::to_string(step) + "_" + what + ".bin";
}

void WriteBytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error(path + ": cannot write");
}

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read (run --write first)");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

PixelState ReadState(const std::string& path) {
  PixelState state;
  if (!DeserializePixelState(ReadBytes(path), &state)) {
    throw std::runtime_error(path + ": not a pixel state");
  }
  return state;
}

void Write(const std::string& dir) {
  const SelfCheckProblem problem;
  CpuSweepEngine cpu(kNumThreads);
  PixelState state = problem.EmptyState();
  for (int step = 0; step < NumSelfCheckSteps(); ++step) {
    WriteBytes(StepFile(dir, step, "start"), SerializePixelState(state));
    const std::vector<uint8_t> classes = RunSelfCheckStep(step, problem, cpu, kNumThreads, &state);
    WriteBytes(StepFile(dir, step, "result"), SerializePixelState(state));
    WriteBytes(StepFile(dir, step, "classes"), std::string(classes.begin(), classes.end()));
  }
}

bool Compare(const std::string& dir) {
  const SelfCheckProblem problem;
  CpuSweepEngine cpu(kNumThreads);
  bool passed = true;
  for (int step = 0; step < NumSelfCheckSteps(); ++step) {
    PixelState state = ReadState(StepFile(dir, step, "start"));
    const std::vector<uint8_t> classes = RunSelfCheckStep(step, problem, cpu, kNumThreads, &state);
    const std::string written = ReadBytes(StepFile(dir, step, "classes"));
    const double share = SelfCheckDifferingShare(
        ReadState(StepFile(dir, step, "result")),
        std::vector<uint8_t>(written.begin(), written.end()), state, classes);
    passed = passed && share <= kSelfCheckMaxDifferingShare;
    std::printf("  %-32s %5.2f %% of the pixels differ\n", SelfCheckStepName(step), 100.0 * share);
  }
  std::printf("  (bound %.2f %% in each step, as the device self-check)\n",
              100.0 * kSelfCheckMaxDifferingShare);
  return passed;
}

}  // namespace
}  // namespace msp

int main(int argc, char** argv) {
  std::string write_dir, compare_dir;
  msp::ToolCommandLine command_line(
      "Usage: msp_core_steps (--write DIR | --compare DIR)",
      "The device self-check's steps on this build's CPU core: --write keeps each\n"
      "step's start and result, --compare runs each step from a written start and\n"
      "prints the share of pixels differing from the written result.");
  command_line.Add("write", &write_dir, "Folder to write the steps' states to.");
  command_line.Add("compare", &compare_dir, "Folder of written states to compare with.");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    if (write_dir.empty() == compare_dir.empty()) {
      throw std::invalid_argument("give one of --write DIR and --compare DIR");
    }
    if (!write_dir.empty()) {
      msp::Write(write_dir);
      return 0;
    }
    return msp::Compare(compare_dir) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
}
