#include "tools/evaluate/edge_regions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>

namespace msp {
namespace eval {
namespace {

bool HasDepth(float d) { return d > 0.0f; }

// The kDepthEdgeJump test between two pixels that both have depth.
bool IsDepthJump(float a, float b) {
  return std::abs(static_cast<double>(a) - b) > kDepthEdgeJump * std::min(a, b);
}

// Mean colour of the pixels k = 1..kEdgeSideSamples steps of (dr, dc) beyond
// (row, col) that stay on its surface; false when fewer than
// kMinEdgeSideSamples do.
bool SideColour(const DenseMap& gt, const cv::Mat& image, int row, int col, int dr, int dc,
                double mean[3]) {
  const float d0 = gt.At(row, col);
  double sum[3] = {0, 0, 0};
  int n = 0;
  for (int k = 1; k <= kEdgeSideSamples; ++k) {
    const int r = row + k * dr, c = col + k * dc;
    if (r < 0 || r >= gt.height || c < 0 || c >= gt.width) break;
    const float d = gt.At(r, c);
    // Beyond a depth edge the samples belong to another surface.
    if (!HasDepth(d) || IsDepthJump(d, d0)) break;
    const cv::Vec3b& v = image.at<cv::Vec3b>(r, c);
    for (int ch = 0; ch < 3; ++ch) sum[ch] += v[ch];
    ++n;
  }
  if (n < kMinEdgeSideSamples) return false;
  for (int ch = 0; ch < 3; ++ch) mean[ch] = sum[ch] / n;
  return true;
}

// The edge between (r0, c0) and its neighbour (r0 + dr, c0 + dc): do its
// sides look alike (kAlikeColourDistance)?
bool AlikeSides(const DenseMap& gt, const cv::Mat& image, int r0, int c0, int dr, int dc) {
  double a[3], b[3];
  if (!SideColour(gt, image, r0, c0, -dr, -dc, a) ||
      !SideColour(gt, image, r0 + dr, c0 + dc, dr, dc, b)) {
    return false;
  }
  double sq = 0.0;
  for (int ch = 0; ch < 3; ++ch) sq += (a[ch] - b[ch]) * (a[ch] - b[ch]);
  return std::sqrt(sq) < kAlikeColourDistance;
}

// The pixels within `radius` (Chebyshev distance) of a marked pixel, kept
// where the ground truth has depth: 255 inside.
cv::Mat Band(const cv::Mat& marks, const DenseMap& gt, int radius) {
  cv::Mat band;
  cv::dilate(marks, band,
             cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * radius + 1, 2 * radius + 1)));
  for (int r = 0; r < gt.height; ++r) {
    for (int c = 0; c < gt.width; ++c) {
      if (!HasDepth(gt.At(r, c))) band.at<uint8_t>(r, c) = 0;
    }
  }
  return band;
}

}  // namespace

int EdgeBandRadius(int gt_width, int gt_height, int map_width, int map_height) {
  double ratio = 1.0;
  if (map_width > 0) ratio = std::max(ratio, static_cast<double>(gt_width) / map_width);
  if (map_height > 0) ratio = std::max(ratio, static_cast<double>(gt_height) / map_height);
  return static_cast<int>(std::lround(kEdgeBandPixels * ratio));
}

EdgeRegions FindEdgeRegions(const DenseMap& gt_depth, const cv::Mat& image, int band_radius) {
  const int w = gt_depth.width, h = gt_depth.height;
  cv::Mat edge(h, w, CV_8UC1, cv::Scalar(0)), alike(h, w, CV_8UC1, cv::Scalar(0));
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const float d = gt_depth.At(r, c);
      if (!HasDepth(d)) continue;
      // Each 4-neighbour pair once: the right and the lower neighbour.
      const int steps[2][2] = {{0, 1}, {1, 0}};
      for (const auto& step : steps) {
        const int r1 = r + step[0], c1 = c + step[1];
        if (r1 >= h || c1 >= w) continue;
        const float d1 = gt_depth.At(r1, c1);
        if (!HasDepth(d1) || !IsDepthJump(d, d1)) continue;
        edge.at<uint8_t>(r, c) = edge.at<uint8_t>(r1, c1) = 255;
        if (AlikeSides(gt_depth, image, r, c, step[0], step[1])) {
          alike.at<uint8_t>(r, c) = alike.at<uint8_t>(r1, c1) = 255;
        }
      }
    }
  }
  EdgeRegions regions;
  regions.near_edge = Band(edge, gt_depth, band_radius);
  regions.alike_edge = Band(alike, gt_depth, band_radius);
  return regions;
}

}  // namespace eval
}  // namespace msp
