// Ideal segmentation masks of the bundled scene: the surface the pixel-centre
// ray of each pixel hits (the ray of its ground-truth depth), labelled at
// three granularities in the layout of the segmentation prior's mask layers
// (docs/segmentation_masks.md). They are what a perfect segmenter would give
// the prior: a measuring tool, the ceiling of what a segmenter can give.
#pragma once

#include <array>
#include <opencv2/core.hpp>

#include "tools/scene/camera_rig.h"
#include "tools/scene/scene.h"

namespace msp {
namespace scene {

// Levels, coarse to fine:
//   0 object: one id per shape, the whole room one id;
//   1 face: each face of the room and of a box, the sphere, a cylinder's side
//     and each of its caps (Hit::face);
//   2 face x paint: level 1 split by material and, on a two-colour pattern
//     (checker, stripes), by which of its two colours covers the point
//     (Scene::Paint).
// Every level-(k+1) region lies inside one level-k region.
constexpr int kNumIdealMaskLevels = 3;

// Ids are fixed by the scene, not by the view: a surface has the same id in
// every image. 0 = unlabelled (a ray that hits nothing: the sky).
using IdealMasks = std::array<cv::Mat, kNumIdealMaskLevels>;  // CV_16UC1 each

// The id of `hit` (from Scene::Intersect) at `level`, in [1, 65535]. Throws
// std::runtime_error when the scene has too many shapes or materials for
// 16-bit ids at that level.
int SurfaceId(const Scene& scene, const Hit& hit, int level);

// The three levels of one view, each view.height x view.width, from the
// pixel-centre ray of every pixel (GroundTruthAt: integer index = image
// point, as the ground-truth depth).
IdealMasks RenderIdealMasks(const Scene& scene, const PinholeView& view);

}  // namespace scene
}  // namespace msp
