// How --PatchMatchStereo.cache_size is shared among what is kept between the
// image-passes of a run, so that together they stay within it whatever the
// number of images (README, "Memory"). The shares follow the bytes per pixel
// each holds: per-image state about 33, images 16 (7 with the colour kept
// as 8-bit pixels), label layers 12 to 16.
#pragma once

#include <cstddef>

namespace msp {

struct CacheBudget {
  size_t state_bytes = 0;  // per-image PatchMatch state (StateCache)
  size_t image_bytes = 0;  // working-resolution images kept from the start
  size_t layer_bytes = 0;  // the segmentation prior's label layers of a round
};

inline CacheBudget SplitCacheSize(double cache_size_gigabytes) {
  constexpr double kBytesPerGigabyte = 1024.0 * 1024.0 * 1024.0;
  const double total = cache_size_gigabytes * kBytesPerGigabyte;
  CacheBudget budget;
  budget.state_bytes = static_cast<size_t>(total / 2);
  budget.image_bytes = static_cast<size_t>(total / 4);
  budget.layer_bytes = static_cast<size_t>(total / 4);
  return budget;
}

}  // namespace msp
