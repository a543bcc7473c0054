// Normals of the written maps from the maps' own depth (docs/method.md
// section 2.9): the normal of each pixel is the plane fitted (least squares,
// principal axes) to the 3D points of the pixels around it that have a depth
// on the same surface. A plane the sweeps found on a weakly textured window
// fixes its depth far better than its tilt: the cost barely changes with the
// normal, and the normals scatter by 20 degrees where the depths agree to a
// percent. COLMAP's fusion joins only pixels whose normals agree within 10
// degrees, so the scattered normals, not the depths, kept right surface out
// of the fused cloud.
#pragma once

#include "base/dense_map.h"
#include "core/math/camera.h"

namespace msp {

// Radius (pixels) of the neighbourhood at an image of `width` x `height`.
int DepthNormalRadius(int width, int height);

// Replaces the normal (3 channels, camera frame) of every pixel of `depth`
// (1 channel, 0 = none) that has at least 6 neighbours within `radius`
// (sampled every radius / 4 pixels) whose depth is within 3 % of its own, by
// the normal of their best-fitting plane, facing the camera. Other pixels keep
// theirs.
void NormalsFromDepth(const core::Camera& camera, const DenseMap& depth, int radius,
                      int num_threads, DenseMap* normal);

}  // namespace msp
