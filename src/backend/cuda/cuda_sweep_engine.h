// The CUDA back-end's sweeps: each step uploads the pass's inputs and state
// to the GPU of the image's worker (DevicePass), runs the step's kernel(s)
// and downloads the state, so the schedule's CPU steps between them (the
// median filter, segment planes, the prior, upsampling, the output filter,
// and the deformable step's whole-image parts: the nearest reliable pixels,
// the confining edges' nearest pixels, the prior's anchors) see the same
// host arrays as with the CPU back-end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "deformable/deformable_sweeps.h"
#include "engine/sweep_engine.h"

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
  std::vector<uint8_t> Classify(const core::PassParams& params,
                                const core::ReliabilityParams& rp) override;
  // The anchor searches and sweeps of every iteration on the device
  // (cuda_deformable.cc); the anchors go to the device in row bands when
  // they do not fit at once (PlanRowBands).
  DeformableStats DeformableIterations(const core::PassParams& params, const ReliabilityMaps& maps,
                                       const DeformableSettings& settings, int num_iterations,
                                       std::vector<core::PriorAnchors>* prior_anchors) override;
  // Caps the device memory of one band of deformable anchors (0 = what is
  // free): a small image then runs in several bands, as a large one would.
  void LimitDeformableBandBytes(size_t bytes) { band_bytes_limit_ = bytes; }
  // Prints the peak device memory of every device used.
  void Finish() override;

 private:
  // Uploads the pass to the image's device, runs step(pass), downloads the state.
  template <typename Step>
  void OnDevice(const core::PassParams& params, Step step);
  // OnDevice with a class buffer: launch(pass, device_classes), then the classes.
  template <typename Launch>
  std::vector<uint8_t> ClassesOnDevice(const core::PassParams& params, Launch launch);

  // Makes the image's device current and returns it.
  int ImageDevice(const core::PassParams& params);

  std::map<uint32_t, int> device_of_image_;
  int default_device_;
  std::vector<int> used_devices_;
  // The host's copies of the deformable step's slots, anchors, hits and
  // sampling solutions, kept from one pass to the next.
  DeformableBuffers deformable_host_;
  size_t band_bytes_limit_ = 0;
};

}  // namespace cuda
}  // namespace msp
