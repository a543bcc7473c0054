// The gpu tests run where a CUDA device exists and skip with the reason
// elsewhere (the CUDA build compiles them on every machine).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "backend/device_query.h"

namespace msp {
namespace test {

// The first CUDA device, or none with *why_none saying why.
inline std::vector<DeviceInfo> CudaDevices(std::string* why_none) {
  return MakeDeviceQuery()->Devices(why_none);
}

}  // namespace test
}  // namespace msp

// Skips the test, with the reason, when no CUDA device is present.
#define MSP_SKIP_WITHOUT_GPU()                                                                  \
  do {                                                                                          \
    std::string msp_why_none_;                                                                  \
    if (::msp::test::CudaDevices(&msp_why_none_).empty()) {                                     \
      GTEST_SKIP() << "no CUDA device on this machine (" << msp_why_none_                       \
                   << "); the CPU/GPU parity is checked where one exists (bench/gpu_check.sh)"; \
    }                                                                                           \
  } while (0)
