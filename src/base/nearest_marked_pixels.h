// Nearest reliable pixel of every pixel (docs/method.md section 3.2): an unreliable ray
// hit of the anchor search snaps to it. An exact Euclidean feature transform
// (Felzenszwalb & Huttenlocher's lower envelope of parabolas, a column pass
// then a row pass), linear in the number of pixels, instead of a 201x201 scan.
// The same transform of the depth edges lets the confined search skip walks
// that cannot reach an edge.
#pragma once

#include <cstdint>
#include <vector>

namespace msp {

// For each pixel, the index (row * width + col) of a reliable pixel
// (classes[i] == core::kReliable) at the smallest Euclidean distance, or -1
// when the image has none. Ties go to any of the nearest ones.
std::vector<int> NearestReliablePixels(const uint8_t* classes, int width, int height,
                                       int num_threads);

// The same transform for the pixels with a nonzero mark (e.g. the depth edges
// that confine the anchor search): the nearest marked pixel, or -1.
std::vector<int> NearestMarkedPixels(const uint8_t* marks, int width, int height, int num_threads);

}  // namespace msp
