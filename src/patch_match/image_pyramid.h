// Coarse-to-fine rounds of the APD schedule: images and cameras halved per
// level, and the planes of a finished round carried up to the next one.
#pragma once

#include "base/dense_map.h"
#include "core/math/camera.h"
#include "patch_match/pixel_state.h"

namespace msp {

// Number of halvings until the larger side is <= coarsest_size (0 when it already is).
int NumHalvings(int width, int height, int coarsest_size);

// 2x2 box average; odd sizes drop the last row/column.
DenseMap DownsampleHalf(const DenseMap& image);

// Camera for the halved image. With COLMAP's convention (pixel index = image
// point), coarse pixel i covers fine pixels 2i and 2i+1, centred at 2i + 0.5.
core::Camera HalveCamera(const core::Camera& camera, int new_width, int new_height);

// Planes of `coarse` (camera `coarse_cam`) carried to every pixel of the finer
// image (camera `fine_cam`): each fine pixel continues the plane of the coarse
// pixel it falls in, and takes its view mask and prior edge bits. Costs are
// left at the maximum: the next pass rescores.
PixelState UpsampleState(const PixelState& coarse, const core::Camera& coarse_cam,
                         const core::Camera& fine_cam);

}  // namespace msp
