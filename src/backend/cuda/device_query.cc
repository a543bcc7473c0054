// The CUDA runtime's answer to the back-end choice: the devices present, with
// their free memory and what the kernels reserve on each, and the device
// self-check run by the CUDA sweeps.
#include "backend/device_query.h"

#include <cuda_runtime.h>

#include <exception>
#include <string>

#include "backend/cuda/cuda_check.h"
#include "backend/cuda/cuda_sweep_engine.h"
#include "backend/cuda/kernel_reserve.h"
#include "backend/device_self_check.h"

namespace msp {
namespace {

// The CPU side of the self-check: its problem is a few thousand pixels,
// a fraction of a second on one thread.
constexpr int kSelfCheckCpuThreads = 1;

class CudaDeviceQuery : public DeviceQuery {
 public:
  bool CudaBuilt() const override { return true; }

  std::vector<DeviceInfo> Devices(std::string* why_none) const override {
    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess) {
      // No driver or no device: not an error here, the choice falls back or says why.
      cudaGetLastError();
      *why_none = std::string("cudaGetDeviceCount: ") + cudaGetErrorString(status);
      return {};
    }
    if (count == 0) *why_none = "cudaGetDeviceCount found 0 devices";
    std::vector<DeviceInfo> devices;
    for (int d = 0; d < count; ++d) {
      // A device the runtime lists but cannot open (a driver too old for
      // this build, a device in use exclusively) is left out, with why, so
      // that auto falls back to the CPU instead of stopping.
      try {
        devices.push_back(Describe(d));
      } catch (const std::exception& e) {
        cudaGetLastError();
        if (!why_none->empty()) *why_none += "; ";
        *why_none += "device " + std::to_string(d) + ": " + e.what();
      }
    }
    return devices;
  }

  SelfCheckReport SelfCheck(const DeviceInfo& device) const override {
    try {
      // The problem's image runs on the engine's default device.
      cuda::CudaSweepEngine engine({}, device.index);
      return SelfCheckAgainstCpu(engine, kSelfCheckCpuThreads);
    } catch (const std::exception& e) {
      cudaGetLastError();  // leave no error behind for the CPU run that follows
      return SelfCheckReport{false, e.what()};
    }
  }

 private:
  static DeviceInfo Describe(int device) {
    cudaDeviceProp prop;
    MSP_CUDA_CHECK(cudaGetDeviceProperties(&prop, device));
    MSP_CUDA_CHECK(cudaSetDevice(device));
    DeviceInfo info;
    info.index = device;
    info.name = prop.name;
    info.compute_major = prop.major;
    info.compute_minor = prop.minor;
    MSP_CUDA_CHECK(cudaMemGetInfo(&info.free_bytes, &info.total_bytes));
    info.reserve_bytes = cuda::KernelReserveBytes(device);
    return info;
  }
};

}  // namespace

std::unique_ptr<DeviceQuery> MakeDeviceQuery() { return std::make_unique<CudaDeviceQuery>(); }

}  // namespace msp
