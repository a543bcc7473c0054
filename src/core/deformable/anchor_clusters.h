// Disassemble-clustering (paper "Disassemble-Clustering", docs/method.md
// section 6): every anchor within the RANSAC threshold is kept (up to one per
// ray hit, four times APD's eight), the kept anchors are grouped by DBSCAN in
// image space, and each cluster becomes one lane of the deformable patch: its
// k anchors each get a sub-patch of side w / k and their share of the lane's
// samples, so a dense group of anchors counts once in eq. 3's mean, as one
// isolated anchor does.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/deformable/anchor_windows.h"
#include "core/deformable/anchors.h"
#include "core/deformable/deformable_limits.h"
#include "core/math/hd.h"
#include "core/math/rng.h"
#include "core/math/vec.h"

namespace msp {
namespace core {

// DBSCAN: a core point has at least eta neighbours within gamma. Automatic
// gamma: a quarter of the median anchor distance to p, at least 3 px, so
// that anchors on neighbouring rays of one sector join while those of
// different sectors at the same radius (45 degrees apart, 0.77 r) do not.
constexpr int kDefaultDbscanEta = 2;
constexpr float kMinAutomaticDbscanGamma = 3.0f;        // px
constexpr float kDbscanGammaPerMedianDistance = 0.25f;  // of the median anchor distance
// The lane's samples, as APD's 3x3 anchor window has (paper: 9 / k_i per sub-patch).
constexpr int kClusterLaneSamples = 9;
static_assert(kClusterLaneSamples <= kMaxAnchorWindowSamples, "a lane holds its samples");

struct ClusterParams {
  int eta;      // neighbours (the point itself not counted) that make a core point
  float gamma;  // neighbourhood radius in px; <= 0 = automatic (AutomaticDbscanGamma)
};

MSP_HD ClusterParams DefaultClusterParams() { return ClusterParams{kDefaultDbscanEta, 0.0f}; }

// max(3 px, 0.25 x the median distance of the n points to (col, row)); the
// median of an even count is the mean of the two middle distances.
MSP_HD float AutomaticDbscanGamma(const float* x, const float* y, int n, int col, int row) {
  float d[kMaxKeptAnchors];
  const int m = n < kMaxKeptAnchors ? n : kMaxKeptAnchors;
  for (int k = 0; k < m; ++k) {
    const float dx = x[k] - static_cast<float>(col), dy = y[k] - static_cast<float>(row);
    float v = sqrtf(dx * dx + dy * dy);
    int j = k;
    for (; j > 0 && d[j - 1] > v; --j) d[j] = d[j - 1];  // insertion sort
    d[j] = v;
  }
  const float median = m == 0 ? 0.0f : (m % 2 == 1 ? d[m / 2] : 0.5f * (d[m / 2 - 1] + d[m / 2]));
  return fmaxf(kMinAutomaticDbscanGamma, kDbscanGammaPerMedianDistance * median);
}

// DBSCAN of n <= kMaxKeptAnchors points: label[k] receives point k's
// cluster; returns the number of clusters. Core points (>= eta others within
// gamma) within gamma of each other chain into one cluster; a border point
// (not core, within gamma of a core) joins the cluster of its nearest core
// (ties: the lower index); every other point is a cluster of its own.
// Clusters are numbered in the order of their lowest core, then the
// isolated points in index order: the result depends on the order of the
// points only through the numbering.
MSP_HD int Dbscan(const float* x, const float* y, int n, int eta, float gamma, int* label) {
  const float gamma2 = gamma * gamma;
  bool core[kMaxKeptAnchors];
  for (int a = 0; a < n; ++a) {
    int neighbours = 0;
    for (int b = 0; b < n; ++b) {
      const float dx = x[a] - x[b], dy = y[a] - y[b];
      neighbours += (b != a && dx * dx + dy * dy <= gamma2) ? 1 : 0;
    }
    core[a] = neighbours >= eta;
    label[a] = -1;
  }
  int num_clusters = 0;
  int stack[kMaxKeptAnchors];
  for (int a = 0; a < n; ++a) {
    if (!core[a] || label[a] >= 0) continue;
    int top = 0;
    stack[top++] = a;
    label[a] = num_clusters;
    while (top > 0) {
      const int c = stack[--top];
      for (int b = 0; b < n; ++b) {
        const float dx = x[c] - x[b], dy = y[c] - y[b];
        if (core[b] && label[b] < 0 && dx * dx + dy * dy <= gamma2) {
          label[b] = num_clusters;
          stack[top++] = b;
        }
      }
    }
    ++num_clusters;
  }
  for (int a = 0; a < n; ++a) {
    if (core[a]) continue;
    int nearest = -1;
    float nearest2 = gamma2;
    for (int b = 0; b < n; ++b) {
      const float dx = x[a] - x[b], dy = y[a] - y[b];
      const float d2 = dx * dx + dy * dy;
      if (core[b] && d2 <= gamma2 && (nearest < 0 || d2 < nearest2)) {
        nearest = b;
        nearest2 = d2;
      }
    }
    if (nearest >= 0) label[a] = label[nearest];
  }
  for (int a = 0; a < n; ++a) {
    if (label[a] < 0) label[a] = num_clusters++;
  }
  return num_clusters;
}

// The clusters that become lanes: cluster c holds the anchors
// member[start[c] .. start[c + 1]) (indices into the AnchorSet, ascending,
// so closest to the plane first).
struct AnchorClusters {
  int count;  // at most kMaxAnchors
  int start[kMaxAnchors + 1];
  int member[kMaxKeptAnchors];
  MSP_HD int size(int c) const { return start[c + 1] - start[c]; }
};

// DBSCAN of the anchors around pixel (col, row). With more than kMaxAnchors
// clusters (a vector holds that many lanes), the largest are kept; ties go
// to the cluster nearer to p (its nearest anchor), then to the one holding
// the anchor closest to the plane. The anchors of the other clusters take no
// part in the cost. Lanes are in that order.
MSP_HD void ClusterAnchors(const AnchorSet& anchors, int col, int row, const ClusterParams& params,
                           AnchorClusters* out) {
  const int n = anchors.count < kMaxKeptAnchors ? anchors.count : kMaxKeptAnchors;
  float x[kMaxKeptAnchors] = {}, y[kMaxKeptAnchors] = {};  // zeroed: silences a false warning
  for (int k = 0; k < n; ++k) {
    x[k] = static_cast<float>(anchors.cols[k]);
    y[k] = static_cast<float>(anchors.rows[k]);
  }
  const float gamma = params.gamma > 0.0f ? params.gamma : AutomaticDbscanGamma(x, y, n, col, row);
  int label[kMaxKeptAnchors];
  const int num = Dbscan(x, y, n, params.eta, gamma, label);
  int size[kMaxKeptAnchors], first[kMaxKeptAnchors];
  float near2[kMaxKeptAnchors];
  for (int c = 0; c < num; ++c) {
    size[c] = 0;
    first[c] = n;
    near2[c] = 1e30f;
  }
  for (int k = 0; k < n; ++k) {
    const int c = label[k];
    const float dx = x[k] - static_cast<float>(col), dy = y[k] - static_cast<float>(row);
    ++size[c];
    first[c] = k < first[c] ? k : first[c];
    near2[c] = fminf(near2[c], dx * dx + dy * dy);
  }
  bool taken[kMaxKeptAnchors] = {};
  out->count = 0;
  out->start[0] = 0;
  while (out->count < kMaxAnchors) {
    int best = -1;
    for (int c = 0; c < num; ++c) {
      if (taken[c]) continue;
      const bool better =
          best < 0 || size[c] > size[best] ||
          (size[c] == size[best] &&
           (near2[c] < near2[best] || (near2[c] == near2[best] && first[c] < first[best])));
      if (better) best = c;
    }
    if (best < 0) break;
    taken[best] = true;
    int end = out->start[out->count];
    for (int k = 0; k < n; ++k) {
      if (label[k] == best) out->member[end++] = k;
    }
    out->start[++out->count] = end;
  }
  for (int c = out->count + 1; c <= kMaxAnchors; ++c) out->start[c] = out->start[out->count];
}

// Every anchor a cluster of its own, the first kMaxAnchors (APD's anchors):
// sampling randomization without clustering.
MSP_HD void SingletonClusters(const AnchorSet& anchors, AnchorClusters* out) {
  out->count = anchors.count < kMaxAnchors ? anchors.count : kMaxAnchors;
  for (int c = 0; c <= kMaxAnchors; ++c) {
    out->start[c] = c < out->count ? c : out->count;
    if (c < out->count) out->member[c] = c;
  }
}

// Samples of the m-th of k anchors of a cluster: n / k each, the remainder
// one more each to the first anchors (closest to the plane). With k > n the
// anchors past the n-th get none.
MSP_HD int SubPatchSamples(int m, int k, int n) { return n / k + (m < n % k ? 1 : 0); }

// Half side in whole pixels of the sub-patch of an anchor in a cluster of
// k: side w / k, w = 2 radius + 1 the anchor window's side (k = 1: the
// whole window; from k = 6 on, the anchor pixel alone).
MSP_HD int SubPatchHalfSide(int radius, int k) {
  const float side = static_cast<float>(2 * radius + 1) / static_cast<float>(k);
  const int half = static_cast<int>(floorf(0.5f * (side - 1.0f) + 0.5f));
  return half > 0 ? half : 0;
}

// The fixed sampling grid of n samples in a sub-patch of half side h: unit
// offsets on the 3x3 grid {-1, 0, 1}^2, scaled by h. Nine samples fill it
// row by row, as APD's window; fewer take the centre and corners first
// (odd counts) or the corners first (even counts), spreading them.
MSP_HD void SubPatchGridOffset(int t, int n, int h, int* dx, int* dy) {
  constexpr int kOddX[9] = {0, -1, 1, 1, -1, 0, 0, -1, 1};
  constexpr int kOddY[9] = {0, -1, 1, -1, 1, -1, 1, 0, 0};
  constexpr int kEvenX[9] = {-1, 1, 1, -1, 0, 0, -1, 1, 0};
  constexpr int kEvenY[9] = {-1, 1, -1, 1, -1, 1, 0, 0, 0};
  const int u = t % 9;
  if (n >= 9) {
    *dx = h * (u % 3 - 1);
    *dy = h * (u / 3 - 1);
  } else if (n % 2 == 1) {
    *dx = h * kOddX[u];
    *dy = h * kOddY[u];
  } else {
    *dx = h * kEvenX[u];
    *dy = h * kEvenY[u];
  }
}

// The lanes' samples: cluster c is lane c, its m-th anchor holds
// SubPatchSamples(m, k, kClusterLaneSamples) of them inside its sub-patch,
// in member order. `offset(lane, t, n, h, &dx, &dy)` places sample t of the
// n of a sub-patch of half side h. Samples are clamped into the image (a
// sub-patch at the border is cut by it). The lane's point is its first
// anchor.
template <typename OffsetFn>
MSP_HD void ClusterLaneSamples(const AnchorSet& anchors, const AnchorClusters& clusters, int radius,
                               int width, int height, OffsetFn& offset, LaneSamples* out) {
  out->count = clusters.count;
  out->num_samples = kClusterLaneSamples;
  for (int c = 0; c < kMaxAnchors; ++c) {
    if (c >= clusters.count) {
      out->col[c] = out->row[c] = 0;
      for (int s = 0; s < kClusterLaneSamples; ++s) out->x[s][c] = out->y[s][c] = 0;
      continue;
    }
    const int k = clusters.size(c);
    const int h = SubPatchHalfSide(radius, k);
    const int* member = clusters.member + clusters.start[c];
    out->col[c] = anchors.cols[member[0]];
    out->row[c] = anchors.rows[member[0]];
    int s = 0;
    for (int m = 0; m < k && s < kClusterLaneSamples; ++m) {
      const int n = SubPatchSamples(m, k, kClusterLaneSamples);
      const int ac = anchors.cols[member[m]], ar = anchors.rows[member[m]];
      for (int t = 0; t < n; ++t, ++s) {
        int dx, dy;
        offset(c, t, n, h, &dx, &dy);
        out->x[s][c] = ClampInt(ac + dx, 0, width - 1);
        out->y[s][c] = ClampInt(ar + dy, 0, height - 1);
      }
    }
  }
}

// The fixed grid (no sampling randomization).
struct GridOffsets {
  MSP_HD void operator()(int, int t, int n, int h, int* dx, int* dy) {
    SubPatchGridOffset(t, n, h, dx, dy);
  }
};

MSP_HD void GridClusterSamples(const AnchorSet& anchors, const AnchorClusters& clusters, int radius,
                               int width, int height, LaneSamples* out) {
  GridOffsets grid;
  ClusterLaneSamples(anchors, clusters, radius, width, height, grid, out);
}

}  // namespace core
}  // namespace msp
