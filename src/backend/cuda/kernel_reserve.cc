#include "backend/cuda/kernel_reserve.h"

#include <cuda_runtime.h>

#include <algorithm>

#include "backend/cuda/cuda_check.h"
#include "backend/cuda/deformable_kernels.h"
#include "backend/cuda/sweep_kernels.h"

namespace msp {
namespace cuda {
namespace {

// Kept free for the runtime beyond the kernels' stacks (module loading,
// allocation granularity).
constexpr size_t kRuntimeMarginBytes = 64u << 20;

}  // namespace

size_t KernelReserveBytes(int device) {
  cudaDeviceProp prop;
  MSP_CUDA_CHECK(cudaGetDeviceProperties(&prop, device));
  MSP_CUDA_CHECK(cudaSetDevice(device));
  size_t stack_limit = 0;
  MSP_CUDA_CHECK(cudaDeviceGetLimit(&stack_limit, cudaLimitStackSize));
  const size_t per_thread =
      std::max({stack_limit, MaxKernelLocalBytes(), MaxDeformableKernelLocalBytes()});
  return per_thread * static_cast<size_t>(prop.multiProcessorCount) *
             static_cast<size_t>(prop.maxThreadsPerMultiProcessor) +
         kRuntimeMarginBytes;
}

}  // namespace cuda
}  // namespace msp
