// RAII device memory: a DeviceBuffer owns one cudaMalloc'ed array and frees
// it when it goes out of scope (also when an exception unwinds), so no error
// path leaks device memory. Allocations are counted per device, which gives
// the peak device memory of a run (DeviceMemoryMeter).
#pragma once

#include <cuda_runtime.h>

#include <cstddef>
#include <utility>

#include "backend/cuda/cuda_check.h"

namespace msp {
namespace cuda {

// Bytes held by DeviceBuffers on each device, now and at most.
class DeviceMemoryMeter {
 public:
  static constexpr int kMaxDevices = 64;
  static void Add(int device, size_t bytes);
  static void Remove(int device, size_t bytes);
  static size_t Peak(int device);
  static size_t Current(int device);
};

template <typename T>
class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  explicit DeviceBuffer(size_t count) { Allocate(count); }
  ~DeviceBuffer() { Release(); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  DeviceBuffer(DeviceBuffer&& other) noexcept { *this = std::move(other); }
  DeviceBuffer& operator=(DeviceBuffer&& other) noexcept {
    if (this != &other) {
      Release();
      std::swap(data_, other.data_);
      std::swap(count_, other.count_);
      std::swap(device_, other.device_);
    }
    return *this;
  }

  T* data() const { return data_; }
  size_t size() const { return count_; }
  size_t Bytes() const { return count_ * sizeof(T); }

  // A buffer holding a copy of host[0 .. count).
  static DeviceBuffer FromHost(const T* host, size_t count) {
    DeviceBuffer buffer(count);
    buffer.Upload(host, count);
    return buffer;
  }
  void Upload(const T* host, size_t count) {
    if (count > count_) throw std::runtime_error("DeviceBuffer::Upload: more than allocated");
    if (count > 0)
      MSP_CUDA_CHECK(cudaMemcpy(data_, host, count * sizeof(T), cudaMemcpyHostToDevice));
  }
  void Download(T* host, size_t count) const {
    if (count > count_) throw std::runtime_error("DeviceBuffer::Download: more than allocated");
    if (count > 0)
      MSP_CUDA_CHECK(cudaMemcpy(host, data_, count * sizeof(T), cudaMemcpyDeviceToHost));
  }

 private:
  void Allocate(size_t count) {
    if (count == 0) return;
    MSP_CUDA_CHECK(cudaGetDevice(&device_));
    void* p = nullptr;
    MSP_CUDA_CHECK(cudaMalloc(&p, count * sizeof(T)));
    data_ = static_cast<T*>(p);
    count_ = count;
    DeviceMemoryMeter::Add(device_, Bytes());
  }
  void Release() noexcept {
    if (data_ == nullptr) return;
    // Freeing cannot be reported from a destructor; a failure here means the
    // context is already lost, which the next checked call reports.
    cudaFree(data_);
    DeviceMemoryMeter::Remove(device_, Bytes());
    data_ = nullptr;
    count_ = 0;
  }

  T* data_ = nullptr;
  size_t count_ = 0;
  int device_ = 0;
};

}  // namespace cuda
}  // namespace msp
