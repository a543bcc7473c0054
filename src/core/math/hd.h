// Marks functions shared by the CPU and CUDA back-ends. Everything in
// src/core is header-only, depends only on <cmath>/<cstdint>/<type_traits>
// and other src/core headers, and takes POD arguments, so the same per-pixel
// code compiles for the host and for the device.
#pragma once

#if defined(__CUDACC__)
#define MSP_HD __host__ __device__ __forceinline__
#else
#define MSP_HD inline
#endif
