// The CUDA back-end's sweeps: each step uploads the pass's inputs and state
// to the GPU of the image's worker (DevicePass), runs the step's kernel(s)
// and downloads the state, so the schedule's CPU steps between them (the
// deformable step, the median filter, segment planes, the prior, the output
// filter) see the same host arrays as with the CPU back-end.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "patch_match/sweep_engine.h"

namespace msp {
namespace cuda {

class CudaSweepEngine : public SweepEngine {
 public:
  // `device_of_image`: the CUDA device of each reference image (the
  // PassParams' image_id); images not listed run on `default_device`.
  CudaSweepEngine(std::map<uint32_t, int> device_of_image, int default_device);
  const char* Name() const override { return "CUDA"; }
  void Initialize(const core::PassParams& params) override;
  void Score(const core::PassParams& params) override;
  void Checkerboard(const core::PassParams& params, int num_iterations) override;
  void LocalRefine(const core::PassParams& params) override;
  std::vector<uint8_t> LocalRefineAndClassify(const core::PassParams& params,
                                              const core::ReliabilityParams& rp) override;
  // Prints the peak device memory of every device used.
  void Finish() override;

 private:
  // Makes the image's device current.
  void SelectDevice(const core::PassParams& params);
  // Uploads the pass to the image's device, runs step(pass), downloads the state.
  template <typename Step>
  void OnDevice(const core::PassParams& params, Step step);

  std::map<uint32_t, int> device_of_image_;
  int default_device_;
  std::vector<int> used_devices_;
};

}  // namespace cuda
}  // namespace msp
