// A build without CUDA: no device query, and the CUDA back-end is never chosen.
#include <stdexcept>

#include "backend/cuda/cuda_entry.h"

namespace msp {
namespace {

class NoCudaQuery : public DeviceQuery {
 public:
  bool CudaBuilt() const override { return false; }
  std::vector<DeviceInfo> Devices(std::string* why_none) const override {
    *why_none = "built without CUDA";
    return {};
  }
  SelfCheckReport SelfCheck(const DeviceInfo&) const override {
    return SelfCheckReport{false, "built without CUDA"};
  }
};

}  // namespace

std::unique_ptr<DeviceQuery> MakeDeviceQuery() { return std::make_unique<NoCudaQuery>(); }

void RunPatchMatchCuda(const std::vector<View>&, const std::vector<Problem>&,
                       const PatchMatchStereoOptions&, const MspStereoOptions&, const std::string&,
                       MapSink&, const std::vector<DeviceInfo>&, const SharedRun*) {
  throw std::logic_error("RunPatchMatchCuda: this build has no CUDA back-end");
}

}  // namespace msp
