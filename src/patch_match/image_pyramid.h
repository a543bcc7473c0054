// Coarse-to-fine rounds of the APD schedule: images and cameras halved per
// level, and the planes of a finished round carried up to the next one.
#pragma once

#include "base/dense_map.h"
#include "core/math/camera.h"
#include "engine/pixel_state.h"

namespace msp {

// 2x2 box average; odd sizes drop the last row/column.
DenseMap DownsampleHalf(const DenseMap& image);

// Camera for the halved image. With COLMAP's convention (pixel index = image
// point), coarse pixel i covers fine pixels 2i and 2i+1, centred at 2i + 0.5.
core::Camera HalveCamera(const core::Camera& camera, int new_width, int new_height);

// Planes of `coarse` (camera `coarse_cam`) carried to every pixel of the finer
// image (camera `fine_cam`) by nearest neighbour: each fine pixel continues the
// plane of the coarse pixel it falls in, and takes its view mask and prior
// edge bits. Costs are left at the maximum: the next pass rescores. The
// coarse index is fine index x size ratio: with an odd fine size that puts
// even fine columns (rows) one coarse pixel left of (above) where the cameras
// map them; kept, as --MspStereo.advanced_joint_bilateral_upsampling false promises
// the earlier results.
PixelState UpsampleStateNearest(const PixelState& coarse, const core::Camera& coarse_cam,
                                const core::Camera& fine_cam);

// As UpsampleStateNearest, but each fine pixel continues the plane, and takes
// the view mask, of the coarse pixel among the 3x3 around it that a joint
// bilateral vote picks (src/core/patch_match/joint_bilateral.h): weights from
// the distance and from the grey difference between the fine pixel in
// `fine_guide` and the coarse pixel in `coarse_guide` (the reference image at
// the two levels), so depth edges move to the image edges inside a coarse
// pixel. Prior edge bits stay nearest neighbour's: they mark image locations,
// and their 2-px lines stay whole where the two fine pixels of a coarse edge
// pixel take planes from different neighbours. The fine rows share out over
// up to `num_threads` threads.
PixelState UpsampleStateJointBilateral(const PixelState& coarse, const DenseMap& coarse_guide,
                                       const core::Camera& coarse_cam, const DenseMap& fine_guide,
                                       const core::Camera& fine_cam, int num_threads = 1);

}  // namespace msp
