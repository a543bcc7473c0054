// The pixels around true depth edges: where a matching window or an anchor
// can reach across a surface boundary, the failure the segmentation prior
// targets; and the part of them where the two surfaces look alike, where
// colour cannot tell the method that the edge is there.
#pragma once

#include <opencv2/core.hpp>

#include "base/dense_map.h"

namespace msp {
namespace eval {

// A depth edge lies between two 4-neighbouring ground-truth pixels (both with
// depth > 0) whose depths differ by more than this fraction of the nearer one:
// far above the depth change between neighbours on any surface the scene's
// cameras see at a usable angle, far below the jump from an object to what
// lies behind it.
constexpr double kDepthEdgeJump = 0.03;

// Half-width of the near-edge band in pixels of the evaluated map (a square
// neighbourhood: Chebyshev distance), about a matching window's reach.
constexpr int kEdgeBandPixels = 4;

// An edge's two sides have alike colour when the mean colours of the
// kEdgeSideSamples pixels beyond each of its two pixels, along the line
// through both, differ by less than kAlikeColourDistance: the Euclidean norm
// of the difference of the mean 8-bit RGB values of the reference image. The
// pixels at the edge itself are left out because a camera pixel there mixes
// both surfaces; a side sample counts only while it stays on its pixel's
// surface (no depth edge between them), and a side with fewer than
// kMinEdgeSideSamples such samples leaves the edge unclassified (not alike).
// The bundled scene's edges fall in two groups: alike sides (same paint and
// facing: mostly under 6 levels, sensor noise and shading drift) and distinct
// ones (textured objects, faces turned differently to the light: mostly over
// 25); 10 levels lies in the sparse gap between them.
constexpr int kEdgeSideSamples = 3;
constexpr int kMinEdgeSideSamples = 2;
constexpr double kAlikeColourDistance = 10.0;

// Masks at ground-truth size, CV_8UC1, 255 inside.
struct EdgeRegions {
  cv::Mat near_edge;   // within the band of a depth edge
  cv::Mat alike_edge;  // within the band of a depth edge whose sides have alike colour
};

// Band half-width in ground-truth pixels for a map of map_width x map_height:
// kEdgeBandPixels times the ground-truth / map size ratio (the larger of the
// two axes, at least 1), rounded, so that the band spans kEdgeBandPixels of
// the map's own pixels (8 ground-truth pixels for a 320 px map of 640 px).
int EdgeBandRadius(int gt_width, int gt_height, int map_width, int map_height);

// `image` is the reference image (CV_8UC3, any channel order) at the ground
// truth's size. An edge marks both of its pixels; the masks are those marks
// widened by `band_radius` and kept where the ground truth has depth.
EdgeRegions FindEdgeRegions(const DenseMap& gt_depth, const cv::Mat& image, int band_radius);

}  // namespace eval
}  // namespace msp
