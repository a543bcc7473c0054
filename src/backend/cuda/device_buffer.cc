#include "backend/cuda/device_buffer.h"

#include <algorithm>
#include <atomic>

namespace msp {
namespace cuda {
namespace {

std::atomic<size_t> g_current[DeviceMemoryMeter::kMaxDevices];
std::atomic<size_t> g_peak[DeviceMemoryMeter::kMaxDevices];

int Slot(int device) { return std::clamp(device, 0, DeviceMemoryMeter::kMaxDevices - 1); }

}  // namespace

void DeviceMemoryMeter::Add(int device, size_t bytes) {
  const int d = Slot(device);
  const size_t now = g_current[d].fetch_add(bytes) + bytes;
  size_t peak = g_peak[d].load();
  while (now > peak && !g_peak[d].compare_exchange_weak(peak, now)) {
  }
}

void DeviceMemoryMeter::Remove(int device, size_t bytes) { g_current[Slot(device)] -= bytes; }

size_t DeviceMemoryMeter::Peak(int device) { return g_peak[Slot(device)].load(); }

size_t DeviceMemoryMeter::Current(int device) { return g_current[Slot(device)].load(); }

}  // namespace cuda
}  // namespace msp
