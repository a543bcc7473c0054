// Dilation of a 0/1 pixel mask by a square window: the pixels within
// `radius` (Chebyshev distance, clipped to the image) of a set pixel.
#pragma once

#include <cstdint>
#include <vector>

namespace msp {

// `mask` is width x height, row-major; the result too (values 0 or 1).
std::vector<uint8_t> DilateMask(const std::vector<uint8_t>& mask, int width, int height,
                                int radius);

}  // namespace msp
