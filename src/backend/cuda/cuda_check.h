// Every CUDA runtime call goes through MSP_CUDA_CHECK: a failure throws
// std::runtime_error with the call, the runtime's message and the file and
// line of the call, so an error names where it happened instead of surfacing
// later as a corrupt map or an unrelated failure.
#pragma once

#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

namespace msp {
namespace cuda {

inline void ThrowCudaError(cudaError_t status, const char* call, const char* file, int line) {
  throw std::runtime_error(std::string(file) + ":" + std::to_string(line) + ": " + call +
                           " failed: " + cudaGetErrorName(status) + " (" +
                           cudaGetErrorString(status) + ")");
}

}  // namespace cuda
}  // namespace msp

#define MSP_CUDA_CHECK(call)                                                    \
  do {                                                                          \
    const cudaError_t msp_cuda_status_ = (call);                                \
    if (msp_cuda_status_ != cudaSuccess) {                                      \
      ::msp::cuda::ThrowCudaError(msp_cuda_status_, #call, __FILE__, __LINE__); \
    }                                                                           \
  } while (0)

// After a kernel launch: the launch's own error (bad geometry, no device)
// and, with the synchronisation, any fault inside the kernel.
#define MSP_CUDA_CHECK_LAUNCH()              \
  do {                                       \
    MSP_CUDA_CHECK(cudaGetLastError());      \
    MSP_CUDA_CHECK(cudaDeviceSynchronize()); \
  } while (0)
