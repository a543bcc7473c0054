// A dense, roughly uniform sample of the surface seen by at least one view,
// with the number of views that see each sample: the reference for the
// evaluator's point-cloud accuracy and completeness.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "tools/scene/camera_rig.h"
#include "tools/scene/renderer.h"
#include "tools/scene/scene.h"

namespace msp {
namespace scene {

// 1 cm: finer than a pixel's footprint at the views' distances (~0.5-1 cm
// here is what one pixel covers), coarse enough to keep the sample small.
constexpr double kSurfaceSampleSpacing = 0.01;

struct SurfaceSample {
  std::vector<Eigen::Vector3f> points;   // world
  std::vector<Eigen::Vector3f> normals;  // world, unit
  std::vector<uint8_t> num_views;        // views that see the point (in image, unoccluded)
  Eigen::Vector3d bbox_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bbox_max = Eigen::Vector3d::Zero();
  double Extent() const { return (bbox_max - bbox_min).norm(); }
};

// Voxel key of a point; 21 bits per axis cover +-10 km at 1 cm. The grid is
// shifted by half a cell so that the scene's planes, all at round
// coordinates, lie mid-cell: on a cell boundary, rounding noise would split
// one plane over two layers of cells and double its sample density.
uint64_t VoxelKey(const Eigen::Vector3d& p, double spacing);

// bbox_min / bbox_max from the points (left at zero when there are none).
void SetBoundingBox(SurfaceSample* sample);

// Back-projects every pixel of every rendered view (its ground-truth depth and
// normal), keeps the first point per `spacing` voxel in view / row / column
// order, then counts visibility in all views by ray casting.
SurfaceSample SampleVisibleSurface(const Scene& scene, const std::vector<PinholeView>& views,
                                   const std::vector<RenderedView>& rendered,
                                   double spacing = kSurfaceSampleSpacing);

// Binary little-endian PLY: float x y z nx ny nz, uchar num_views.
void WriteSurfacePly(const std::string& path, const SurfaceSample& sample);

}  // namespace scene
}  // namespace msp
