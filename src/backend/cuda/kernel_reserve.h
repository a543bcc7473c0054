// What a device needs beyond the run's buffers: the kernels' local memory
// (stack) for every thread that can be resident at once, and a margin for
// the runtime. The back-end choice reports it (DeviceInfo::reserve_bytes)
// and the deformable step keeps it free when it plans its row bands.
#pragma once

#include <cstddef>

namespace msp {
namespace cuda {

// The reserve of CUDA device `device` (makes it current).
size_t KernelReserveBytes(int device);

}  // namespace cuda
}  // namespace msp
