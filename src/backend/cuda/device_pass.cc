#include "backend/cuda/device_pass.h"

namespace msp {
namespace cuda {

DevicePass::DevicePass(const core::PassParams& host)
    : width_(host.state.width),
      height_(host.state.height),
      src_images_(host.num_src),
      src_depths_(host.num_src) {
  core::PassParams device = host;
  device.ref_image = UploadImage(host.ref_image, &ref_image_);
  for (int j = 0; j < host.num_src; ++j) {
    device.src[j].image = UploadImage(host.src[j].image, &src_images_[j]);
    device.src[j].depth = UploadImage(host.src[j].depth, &src_depths_[j]);
  }
  const size_t n = static_cast<size_t>(width_) * height_;
  depth_ = DeviceBuffer<float>::FromHost(host.state.depth, n);
  normal_ = DeviceBuffer<float>::FromHost(host.state.normal, 3 * n);
  cost_ = DeviceBuffer<float>::FromHost(host.state.cost, n);
  mask_ = DeviceBuffer<uint32_t>::FromHost(host.state.mask, n);
  device.state = core::PixelStateView{depth_.data(), normal_.data(), cost_.data(),
                                      mask_.data(),  width_,         height_};
  if (host.unlit != nullptr) {
    unlit_ = DeviceBuffer<uint8_t>::FromHost(host.unlit, n);
    device.unlit = unlit_.data();
  }
  if (host.held != nullptr) {
    held_ = DeviceBuffer<uint8_t>::FromHost(host.held, n);
    device.held = held_.data();
  }
  if (host.window_regions != nullptr) {
    window_regions_ = DeviceBuffer<int32_t>::FromHost(host.window_regions, n);
    device.window_regions = window_regions_.data();
  }
  params_ = DeviceBuffer<core::PassParams>::FromHost(&device, 1);
}

core::ImageView DevicePass::UploadImage(const core::ImageView& view, DeviceBuffer<float>* buffer) {
  if (view.data == nullptr) return view;
  const size_t count = static_cast<size_t>(view.pitch) * (view.height - 1) + view.width;
  *buffer = DeviceBuffer<float>::FromHost(view.data, count);
  return core::ImageView{buffer->data(), view.width, view.height, view.pitch};
}

void DevicePass::DownloadState(const core::PassParams& host) const {
  const size_t n = static_cast<size_t>(width_) * height_;
  depth_.Download(host.state.depth, n);
  normal_.Download(host.state.normal, 3 * n);
  cost_.Download(host.state.cost, n);
  mask_.Download(host.state.mask, n);
}

}  // namespace cuda
}  // namespace msp
