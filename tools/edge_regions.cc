#include "tools/edge_regions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

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

// Square dilation of a 0/1 mask by `radius` (separable running maximum).
std::vector<uint8_t> Dilate(const std::vector<uint8_t>& mask, int width, int height, int radius) {
  std::vector<uint8_t> rows(mask.size(), 0), out(mask.size(), 0);
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      if (!mask[static_cast<size_t>(r) * width + c]) continue;
      const int lo = std::max(0, c - radius), hi = std::min(width - 1, c + radius);
      std::fill(rows.begin() + static_cast<size_t>(r) * width + lo,
                rows.begin() + static_cast<size_t>(r) * width + hi + 1, 1);
    }
  }
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      if (!rows[static_cast<size_t>(r) * width + c]) continue;
      const int lo = std::max(0, r - radius), hi = std::min(height - 1, r + radius);
      for (int rr = lo; rr <= hi; ++rr) out[static_cast<size_t>(rr) * width + c] = 1;
    }
  }
  return out;
}

cv::Mat ToMask(const std::vector<uint8_t>& band, const DenseMap& gt) {
  cv::Mat mask(gt.height, gt.width, CV_8UC1, cv::Scalar(0));
  for (int r = 0; r < gt.height; ++r) {
    for (int c = 0; c < gt.width; ++c) {
      if (band[static_cast<size_t>(r) * gt.width + c] && HasDepth(gt.At(r, c))) {
        mask.at<uint8_t>(r, c) = 255;
      }
    }
  }
  return mask;
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
  std::vector<uint8_t> edge(static_cast<size_t>(w) * h, 0), alike(edge.size(), 0);
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
        const size_t i0 = static_cast<size_t>(r) * w + c, i1 = static_cast<size_t>(r1) * w + c1;
        edge[i0] = edge[i1] = 1;
        if (AlikeSides(gt_depth, image, r, c, step[0], step[1])) alike[i0] = alike[i1] = 1;
      }
    }
  }
  EdgeRegions regions;
  regions.near_edge = ToMask(Dilate(edge, w, h, band_radius), gt_depth);
  regions.alike_edge = ToMask(Dilate(alike, w, h, band_radius), gt_depth);
  return regions;
}

}  // namespace eval
}  // namespace msp
