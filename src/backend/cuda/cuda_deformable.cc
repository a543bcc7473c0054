// CudaSweepEngine::DeformableIterations: the deformable step's anchor
// searches and red-black sweeps on the device, step for step as the CPU's
// RunDeformableCheckerboardIterations (src/deformable/deformable_sweeps.cc),
// whose host parts (the anchor slots, the prior's anchors) it shares.
#include <cuda_runtime.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/cuda/cuda_check.h"
#include "backend/cuda/cuda_sweep_engine.h"
#include "backend/cuda/deformable_kernels.h"
#include "backend/cuda/device_buffer.h"
#include "backend/cuda/device_pass.h"
#include "backend/cuda/kernel_reserve.h"
#include "backend/row_bands.h"
#include "base/log.h"
#include "base/seconds_since.h"
#include "core/deformable/deformable_sweep_pixel.h"
#include "options/option_name.h"
#include "options/stereo_options.h"

namespace msp {
namespace cuda {
namespace {

// Device bytes of one anchor slot: its ray hits, its anchors, its sampling solution.
constexpr size_t kSlotBytes = sizeof(core::AnchorHits) + sizeof(core::AnchorSet) + sizeof(uint32_t);

// The deformable step's whole-image maps on the device
// (kDeviceDeformableBytesPerPixel in backend/device_memory.h).
struct DeviceMaps {
  DeviceBuffer<uint8_t> classes;
  DeviceBuffer<int> nearest, slot;
  DeviceBuffer<uint8_t> edges;
  DeviceBuffer<int> nearest_edge;
  DeviceBuffer<float> depth, normal;  // the iteration's snapshot of the planes
};

// The anchor slots of a band on the device, sized for the largest band.
struct DeviceSlots {
  DeviceBuffer<core::AnchorHits> hits;
  DeviceBuffer<core::AnchorSet> anchors;
  DeviceBuffer<uint32_t> solutions;
};

// Copies host[first, first + count) to device[0, count), or back.
template <typename T>
void ToDevice(const std::vector<T>& host, int first, int count, const DeviceBuffer<T>& device) {
  if (count > 0) {
    MSP_CUDA_CHECK(
        cudaMemcpy(device.data(), host.data() + first, count * sizeof(T), cudaMemcpyHostToDevice));
  }
}
template <typename T>
void ToHost(const DeviceBuffer<T>& device, int first, int count, std::vector<T>* host) {
  if (count > 0) {
    MSP_CUDA_CHECK(
        cudaMemcpy(host->data() + first, device.data(), count * sizeof(T), cudaMemcpyDeviceToHost));
  }
}

// The first slot of every row (and the slot count after the last): slots
// are numbered in pixel order.
std::vector<int> FirstSlotOfRows(const std::vector<int>& slot, int width, int height) {
  std::vector<int> first_slot(height + 1, 0);
  for (int row = 0; row < height; ++row) {
    int count = 0;
    for (int col = 0; col < width; ++col) count += slot[row * width + col] >= 0;
    first_slot[row + 1] = first_slot[row] + count;
  }
  return first_slot;
}

// The whole-image maps on the device, the snapshot unset; *edges becomes the
// device's view of the confining edges.
DeviceMaps UploadMaps(const ReliabilityMaps& maps, const DeformableSettings& settings,
                      const std::vector<int>& slot, core::BoundaryView* edges) {
  const size_t n = slot.size();
  DeviceMaps dev;
  dev.classes = DeviceBuffer<uint8_t>::FromHost(maps.classes.data(), n);
  dev.nearest = DeviceBuffer<int>::FromHost(maps.nearest.data(), n);
  dev.slot = DeviceBuffer<int>::FromHost(slot.data(), n);
  if (edges->data != nullptr) {
    const size_t bytes = static_cast<size_t>(edges->pitch) * edges->height;
    dev.edges = DeviceBuffer<uint8_t>::FromHost(edges->data, bytes);
    edges->data = dev.edges.data();
  }
  if (settings.nearest_edge != nullptr) {
    dev.nearest_edge = DeviceBuffer<int>::FromHost(settings.nearest_edge, n);
  }
  dev.depth = DeviceBuffer<float>(n);
  dev.normal = DeviceBuffer<float>(3 * n);
  return dev;
}

// The row bands whose anchor slots fit in the device memory the whole-image
// buffers, already allocated, left beside the kernels' reserve, and within
// `limit` bytes unless it is 0.
std::vector<RowBand> PlanSlotBands(const std::vector<int>& first_slot, int device,
                                   uint32_t image_id, size_t limit) {
  size_t free_bytes = 0, total_bytes = 0;
  MSP_CUDA_CHECK(cudaMemGetInfo(&free_bytes, &total_bytes));
  const size_t reserve = KernelReserveBytes(device);
  std::vector<size_t> row_bytes(first_slot.size() - 1);
  for (size_t row = 0; row < row_bytes.size(); ++row) {
    row_bytes[row] = (first_slot[row + 1] - first_slot[row]) * kSlotBytes;
  }
  try {
    const size_t budget = free_bytes > reserve ? free_bytes - reserve : 0;
    return PlanRowBands(row_bytes, limit > 0 ? std::min(limit, budget) : budget);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("deformable step of image " + std::to_string(image_id) + " on GPU " +
                             std::to_string(device) + ": " + e.what() + "; run with a smaller " +
                             MSP_OPTION_FLAG_OF(PatchMatchStereoOptions, max_image_size) +
                             " or with " + MSP_OPTION_FLAG_OF(MspStereoOptions, backend) + " cpu");
  }
}

}  // namespace

DeformableStats CudaSweepEngine::DeformableIterations(
    const core::PassParams& params, const ReliabilityMaps& maps, const DeformableSettings& settings,
    int num_iterations, std::vector<core::PriorAnchors>* prior_anchors) {
  const int device = ImageDevice(params);
  const int width = params.state.width, height = params.state.height;
  const size_t n = static_cast<size_t>(width) * height;
  DeformableBuffers& host = deformable_host_;
  const int num_slots = AssignAnchorSlots(maps.classes, &host.slot);
  host.anchors.resize(num_slots);
  host.hits.resize(num_slots);
  if (settings.synergistic) host.solutions.resize(num_slots);
  const std::vector<int> first_slot = FirstSlotOfRows(host.slot, width, height);

  const DevicePass pass(params);
  core::BoundaryView edges = settings.edges;
  const DeviceMaps dev = UploadMaps(maps, settings, host.slot, &edges);
  DeviceBuffer<unsigned long long> anchored(1);

  const std::vector<RowBand> bands =
      PlanSlotBands(first_slot, device, params.image_id, band_bytes_limit_);
  int band_slots = 0;
  for (const RowBand& b : bands) {
    band_slots = std::max(band_slots, first_slot[b.end] - first_slot[b.begin]);
  }
  // One band keeps its slots on the device throughout; several take turns,
  // their slots kept on the host between turns.
  const bool resident = bands.size() <= 1;
  if (!resident) {
    Logf(kLogDetail, "  deformable anchors of %d pixels in %zu row bands on GPU %d\n", num_slots,
         bands.size(), device);
  }
  DeviceSlots slots;
  slots.hits = DeviceBuffer<core::AnchorHits>(band_slots);
  slots.anchors = DeviceBuffer<core::AnchorSet>(band_slots);
  if (settings.synergistic) slots.solutions = DeviceBuffer<uint32_t>(band_slots);

  DeformableBand common{};
  common.slot = dev.slot.data();
  common.maps = core::AnchorMaps{
      dev.classes.data(),     dev.nearest.data(), dev.depth.data(), width, height, edges,
      dev.nearest_edge.data()};
  common.planes = core::PlaneMapView{dev.depth.data(), dev.normal.data(), width, height};
  common.anchor_params = settings.anchors;
  common.cost = settings.cost;
  common.hits = slots.hits.data();
  common.anchors = slots.anchors.data();
  common.solutions = settings.synergistic ? slots.solutions.data() : nullptr;
  common.synergy = settings.synergy;
  const bool shares_pairs = core::SharesAnchorPairs(settings.cost, settings.synergistic);
  auto band_of = [&](const RowBand& b) {
    DeformableBand band = common;
    band.row_begin = b.begin;
    band.row_end = b.end;
    band.slot_begin = first_slot[b.begin];
    return band;
  };

  DeformableStats stats;
  for (int iteration = 0; iteration < num_iterations; ++iteration) {
    MSP_CUDA_CHECK(
        cudaMemcpy(dev.depth.data(), pass.depth(), n * sizeof(float), cudaMemcpyDeviceToDevice));
    MSP_CUDA_CHECK(cudaMemcpy(dev.normal.data(), pass.normal(), 3 * n * sizeof(float),
                              cudaMemcpyDeviceToDevice));
    MSP_CUDA_CHECK(cudaMemset(anchored.data(), 0, sizeof(unsigned long long)));
    common.optimize = iteration < settings.synergy_iterations;
    const auto anchors_start = std::chrono::steady_clock::now();
    for (const RowBand& b : bands) {
      const DeformableBand band = band_of(b);
      const int count = first_slot[b.end] - band.slot_begin;
      if (!resident && iteration > 0) ToDevice(host.hits, band.slot_begin, count, slots.hits);
      LaunchFindAnchors(pass.params(), band, width, iteration, anchored.data());
      if (!resident) {
        ToHost(slots.hits, band.slot_begin, count, &host.hits);
        ToHost(slots.anchors, band.slot_begin, count, &host.anchors);
        if (iteration == 0 && settings.synergistic) {
          ToHost(slots.solutions, band.slot_begin, count, &host.solutions);
        }
      }
    }
    unsigned long long count = 0;
    anchored.Download(&count, 1);
    stats.anchored_updates += static_cast<long long>(count);
    stats.anchor_seconds += SecondsSince(anchors_start);
    if (iteration == 0 && prior_anchors != nullptr) {
      if (resident) ToHost(slots.anchors, 0, num_slots, &host.anchors);
      // The host state is still the first iteration's snapshot.
      CollectPriorAnchors(params.ref_camera, host.slot, host.anchors, params.state.depth, width,
                          height, 1, &host.row_start, prior_anchors);
    }
    const auto sweep_start = std::chrono::steady_clock::now();
    for (int color = 0; color < 2; ++color) {
      for (const RowBand& b : bands) {
        const DeformableBand band = band_of(b);
        const int count = first_slot[b.end] - band.slot_begin;
        if (!resident) {
          ToDevice(host.anchors, band.slot_begin, count, slots.anchors);
          if (settings.synergistic)
            ToDevice(host.solutions, band.slot_begin, count, slots.solutions);
        }
        LaunchDeformableSweep(pass.params(), band, width, color, iteration, shares_pairs);
        if (!resident && settings.synergistic) {
          ToHost(slots.solutions, band.slot_begin, count, &host.solutions);
        }
      }
    }
    stats.sweep_seconds += SecondsSince(sweep_start);
  }
  pass.DownloadState(params);
  return stats;
}

}  // namespace cuda
}  // namespace msp
