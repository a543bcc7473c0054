#include "core/deformable/anchor_clusters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <vector>

#include "tests/support/images.h"

namespace msp {
namespace core {
namespace {

// A textbook DBSCAN by brute force, with this project's rules: core points
// (>= eta others within gamma) in the same connected component of the
// "within gamma" graph of cores share a cluster; a border point takes the
// cluster of its nearest core within gamma (ties: lower index); any other
// point is alone. Returns a cluster id per point (not numbered as Dbscan's).
std::vector<int> ReferenceDbscan(const std::vector<float>& x, const std::vector<float>& y, int eta,
                                 float gamma, std::vector<int>* kind) {
  const int n = static_cast<int>(x.size());
  auto near = [&](int a, int b) {
    return (x[a] - x[b]) * (x[a] - x[b]) + (y[a] - y[b]) * (y[a] - y[b]) <= gamma * gamma;
  };
  std::vector<bool> core(n);
  for (int a = 0; a < n; ++a) {
    int count = 0;
    for (int b = 0; b < n; ++b) count += (a != b && near(a, b));
    core[a] = count >= eta;
  }
  // Components of the cores by repeated relabelling to the smallest id.
  std::vector<int> id(n);
  for (int a = 0; a < n; ++a) id[a] = a;
  for (bool changed = true; changed;) {
    changed = false;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        if (core[a] && core[b] && near(a, b) && id[b] < id[a]) {
          id[a] = id[b];
          changed = true;
        }
      }
    }
  }
  kind->assign(n, 0);  // 0 core, 1 border, 2 isolated
  std::vector<int> label(n);
  for (int a = 0; a < n; ++a) {
    if (core[a]) {
      label[a] = id[a];
      continue;
    }
    int best = -1;
    float best_d2 = 0.0f;
    for (int b = 0; b < n; ++b) {
      const float d2 = (x[a] - x[b]) * (x[a] - x[b]) + (y[a] - y[b]) * (y[a] - y[b]);
      if (core[b] && near(a, b) && (best < 0 || d2 < best_d2)) {
        best = b;
        best_d2 = d2;
      }
    }
    (*kind)[a] = best >= 0 ? 1 : 2;
    label[a] = best >= 0 ? id[best] : n + a;
  }
  return label;
}

// True when two labellings split the points alike.
bool SamePartition(const std::vector<int>& a, const std::vector<int>& b) {
  std::map<int, int> ab, ba;
  for (size_t k = 0; k < a.size(); ++k) {
    if (ab.count(a[k]) && ab[a[k]] != b[k]) return false;
    if (ba.count(b[k]) && ba[b[k]] != a[k]) return false;
    ab[a[k]] = b[k];
    ba[b[k]] = a[k];
  }
  return true;
}

TEST(AnchorClusters, DbscanMatchesABruteForceReference) {
  std::mt19937 random(12345);
  int cores = 0, borders = 0, isolated = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 1 + static_cast<int>(random() % kMaxKeptAnchors);
    const int eta = static_cast<int>(random() % 4);
    const float gamma = 2.0f + static_cast<float>(random() % 80) * 0.1f;
    std::vector<float> x(n), y(n);
    // A few blobs plus scattered points, on whole pixels as anchors are.
    const int blobs = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < n; ++k) {
      const int blob = static_cast<int>(random() % (blobs + 1));
      const float cx = 20.0f * blob, cy = 10.0f * (blob % 2);
      const float spread = blob == blobs ? 60.0f : 8.0f;
      x[k] = std::floor(cx + spread * (static_cast<float>(random() % 1000) / 1000.0f - 0.5f));
      y[k] = std::floor(cy + spread * (static_cast<float>(random() % 1000) / 1000.0f - 0.5f));
    }
    int label[kMaxKeptAnchors];
    const int num = Dbscan(x.data(), y.data(), n, eta, gamma, label);
    std::vector<int> kind;
    const std::vector<int> expected = ReferenceDbscan(x, y, eta, gamma, &kind);
    const std::vector<int> got(label, label + n);
    EXPECT_TRUE(SamePartition(got, expected)) << "trial " << trial;
    for (int k = 0; k < n; ++k) {
      EXPECT_GE(label[k], 0);
      EXPECT_LT(label[k], num);
      cores += kind[k] == 0;
      borders += kind[k] == 1;
      isolated += kind[k] == 2;
    }
  }
  // The trials exercise every kind of point.
  EXPECT_GT(cores, 100);
  EXPECT_GT(borders, 20);
  EXPECT_GT(isolated, 20);
}

TEST(AnchorClusters, CoresChainBordersJoinIsolatedPointsStandAlone) {
  // A chain of cores 2 px apart, a border point 2.5 px off its end, and a
  // point 10 px away from everything.
  const float x[] = {0, 2, 4, 6, 8.5f, 30};
  const float y[] = {0, 0, 0, 0, 0, 0};
  int label[6];
  ASSERT_EQ(Dbscan(x, y, 6, 2, 2.5f, label), 2);
  for (int k = 1; k < 5; ++k) EXPECT_EQ(label[k], label[0]);
  EXPECT_NE(label[5], label[0]);
  // With eta 0 every point is a core; an eta above any count leaves singletons.
  EXPECT_EQ(Dbscan(x, y, 6, 0, 2.5f, label), 2);
  EXPECT_EQ(Dbscan(x, y, 6, 5, 2.5f, label), 6);
}

TEST(AnchorClusters, AutomaticGammaIsAQuarterOfTheMedianDistanceAtLeast3Px) {
  const float x[] = {10, 0, 0, 40};
  const float y[] = {0, 20, 30, 0};
  EXPECT_FLOAT_EQ(AutomaticDbscanGamma(x, y, 4, 0, 0), 0.25f * 25.0f);  // median of 10, 20, 30, 40
  EXPECT_FLOAT_EQ(AutomaticDbscanGamma(x, y, 3, 0, 0), 0.25f * 20.0f);
  EXPECT_FLOAT_EQ(AutomaticDbscanGamma(x, y, 1, 0, 0), 3.0f);
}

// Anchors in groups of given sizes far apart, group g at distance 10 (g + 1)
// from p = (100, 100); members 1 px apart.
AnchorSet Groups(const std::vector<int>& sizes) {
  AnchorSet a{};
  for (size_t g = 0; g < sizes.size(); ++g) {
    for (int m = 0; m < sizes[g]; ++m) {
      a.cols[a.count] = 100 + 10 * static_cast<int>(g + 1) + m;
      a.rows[a.count] = 100 + (g % 2 == 0 ? 1 : -1) * 7 * static_cast<int>(g);
      ++a.count;
    }
  }
  return a;
}

TEST(AnchorClusters, AtMostEightClustersTheLargestFirstTiesNearerToThePixel) {
  // Ten groups: sizes 1, 3, 2, 1, 1, 3, 1, 1, 1, 2 (singletons are isolated).
  const std::vector<int> sizes = {1, 3, 2, 1, 1, 3, 1, 1, 1, 2};
  const AnchorSet anchors = Groups(sizes);
  AnchorClusters c;
  ClusterAnchors(anchors, 100, 100, ClusterParams{1, 1.5f}, &c);
  ASSERT_EQ(c.count, kMaxAnchors);
  // Sizes in lane order: 3 (group 1, nearer), 3 (group 5), 2 (group 2), 2
  // (group 9), then the four singletons nearest to p: groups 0, 3, 4, 6.
  const int expected_size[kMaxAnchors] = {3, 3, 2, 2, 1, 1, 1, 1};
  const int expected_first[kMaxAnchors] = {1, 8, 4, 14, 0, 6, 7, 11};  // first anchor index
  for (int k = 0; k < kMaxAnchors; ++k) {
    EXPECT_EQ(c.size(k), expected_size[k]) << k;
    EXPECT_EQ(c.member[c.start[k]], expected_first[k]) << k;
  }
  // Fewer clusters than lanes: all of them.
  ClusterAnchors(Groups({2, 2, 1}), 100, 100, ClusterParams{1, 1.5f}, &c);
  EXPECT_EQ(c.count, 3);
  EXPECT_EQ(c.start[3], 5);
}

TEST(AnchorClusters, SubPatchSamplesShareTheLaneAndStayInside) {
  for (int k = 1; k <= kMaxKeptAnchors; ++k) {
    int total = 0;
    for (int m = 0; m < k; ++m) {
      const int n = SubPatchSamples(m, k, kClusterLaneSamples);
      EXPECT_GE(n, kClusterLaneSamples / k);
      EXPECT_LE(n, kClusterLaneSamples / k + 1);
      total += n;
    }
    EXPECT_EQ(total, kClusterLaneSamples) << k;
  }
  EXPECT_EQ(SubPatchHalfSide(5, 1), 5);  // the whole 11 px window
  EXPECT_EQ(SubPatchHalfSide(5, 2), 2);  // 5.5 px
  EXPECT_EQ(SubPatchHalfSide(5, 4), 1);  // 2.75 px
  EXPECT_EQ(SubPatchHalfSide(5, 8), 0);  // 1.4 px: the anchor pixel
  // Clusters of 1, 2, 3, 4, 9 and 12 anchors, on a 200x200 image.
  const std::vector<int> sizes = {1, 2, 3, 4, 9, 12};
  AnchorSet anchors{};
  AnchorClusters clusters{};
  clusters.count = static_cast<int>(sizes.size());
  for (size_t c = 0; c < sizes.size(); ++c) {
    clusters.start[c] = anchors.count;
    for (int m = 0; m < sizes[c]; ++m, ++anchors.count) {
      clusters.member[anchors.count] = anchors.count;
      anchors.cols[anchors.count] = 20 + 30 * static_cast<int>(c);
      anchors.rows[anchors.count] = 20 + 12 * m;
    }
  }
  clusters.start[clusters.count] = anchors.count;
  LaneSamples samples;
  GridClusterSamples(anchors, clusters, 5, 200, 200, &samples);
  ASSERT_EQ(samples.count, clusters.count);
  ASSERT_EQ(samples.num_samples, kClusterLaneSamples);
  for (int c = 0; c < clusters.count; ++c) {
    const int k = clusters.size(c);
    const int h = SubPatchHalfSide(5, k);
    int s = 0;
    for (int m = 0; m < k; ++m) {
      const int a = clusters.member[clusters.start[c] + m];
      for (int t = 0; t < SubPatchSamples(m, k, kClusterLaneSamples); ++t, ++s) {
        EXPECT_LE(std::abs(samples.x[s][c] - anchors.cols[a]), h) << c << " " << m;
        EXPECT_LE(std::abs(samples.y[s][c] - anchors.rows[a]), h) << c << " " << m;
      }
    }
    EXPECT_EQ(s, kClusterLaneSamples);
  }
  // A single anchor's lane is APD's 3x3 window at step 5, row by row.
  for (int s = 0; s < 9; ++s) {
    EXPECT_EQ(samples.x[s][0], 20 + 5 * (s % 3 - 1));
    EXPECT_EQ(samples.y[s][0], 20 + 5 * (s / 3 - 1));
  }
  // A sub-patch at the image border is cut by it.
  anchors.cols[0] = 2;
  anchors.rows[0] = 198;
  GridClusterSamples(anchors, clusters, 5, 200, 200, &samples);
  for (int s = 0; s < 9; ++s) {
    EXPECT_GE(samples.x[s][0], 0);
    EXPECT_LT(samples.y[s][0], 200);
  }
}

// Explicit samples on APD's grid prepare the very windows of APD's.
TEST(AnchorClusters, ExplicitSamplesOnTheGridAreApdsWindows) {
  constexpr int kW = 64, kH = 48;
  const test::Image ref = test::NoiseImage(kW, kH, 5);
  const int cols[kMaxAnchors] = {20, 30, 6, 40, 52, 12, 33, 50};
  const int rows[kMaxAnchors] = {20, 25, 20, 36, 10, 8, 30, 40};
  AnchorWindows apd, explicit_windows;
  std::memset(&apd, 0, sizeof(apd));
  std::memset(&explicit_windows, 0, sizeof(explicit_windows));
  PrepareAnchorWindows(ref.View(), cols, rows, 7, 5, 5, &apd);
  LaneSamples samples;
  samples.count = 7;
  samples.num_samples = 9;
  for (int a = 0; a < kMaxAnchors; ++a) {
    samples.col[a] = cols[a];
    samples.row[a] = rows[a];
    for (int s = 0; s < 9; ++s) {
      samples.x[s][a] = cols[a] + 5 * (s % 3 - 1);
      samples.y[s][a] = rows[a] + 5 * (s / 3 - 1);
    }
  }
  PrepareAnchorWindows(ref.View(), samples, 5, &explicit_windows);
  EXPECT_EQ(std::memcmp(&apd, &explicit_windows, sizeof(apd)), 0);
  EXPECT_EQ(apd.fast, 0x7Fu);
}

}  // namespace
}  // namespace core
}  // namespace msp
