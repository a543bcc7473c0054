#include "prior/crf_refinement.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "base/dilate_mask.h"
#include "base/parallel_for.h"

namespace msp {
namespace {

// Pairwise neighbourhood: the (2r+1)^2 window around a pixel. Radius 3 lets a
// label win back a strip up to ~2 px wide, the usual misalignment of a
// segment boundary with the depth edge; an 8-neighbourhood only removes
// isolated pixels, because a wrong strip 2 px wide reinforces itself.
constexpr int kCrfWindowRadius = 3;
constexpr int kWindowNeighbours = (2 * kCrfWindowRadius + 1) * (2 * kCrfWindowRadius + 1) - 1;
// Labels a pixel may take: its own and the most frequent others in its window
// (a window rarely holds more than 3 regions).
constexpr int kMaxCrfLabels = 4;
// Potts weight of a whole window of agreeing, similar neighbours, against
// the unary's log-odds ln(0.7 / 0.3) = 0.85: a window 60/40 split between
// two labels on the same surface overrides the unary; an isolated wrong
// label is always removed.
constexpr float kCrfPairwiseWeight = 10.0f;
constexpr float kPairWeight = kCrfPairwiseWeight / kWindowNeighbours;
// Added to each channel before normalising the RGB colour, so black pixels
// get the grey direction instead of a division by zero.
constexpr float kColorEpsilon = 1e-3f;
// Pairs whose kernel exponent exceeds this (kernel < 6e-6, nothing next to
// the unary's 0.85) are skipped, with their marginal look-ups: across a depth
// edge in the later iterations this is most pairs.
constexpr float kMaxKernelExponent = 12.0f;
// Active pixels handed to one worker at a time.
constexpr int kPixelsPerTask = 512;

// The pixels whose window holds more than one label, each with its candidate
// labels (own label first) and mean-field marginals Q over them.
struct ActiveSet {
  std::vector<int> pixel;       // active index -> pixel index
  std::vector<int> index;       // pixel index -> active index, -1 = single label
  std::vector<int32_t> labels;  // active * kMaxCrfLabels
  std::vector<uint8_t> count;   // candidates per active pixel
};

// Candidate labels of pixel (col, row): its own, then the others of its
// window by decreasing count (ties: smaller id), at most kMaxCrfLabels.
int CollectCandidates(const Segmentation& seg, int col, int row, int32_t* out) {
  int32_t labels[kWindowNeighbours + 1];
  int counts[kWindowNeighbours + 1];
  int distinct = 0;
  for (int r = std::max(0, row - kCrfWindowRadius);
       r <= std::min(seg.height - 1, row + kCrfWindowRadius); ++r) {
    for (int c = std::max(0, col - kCrfWindowRadius);
         c <= std::min(seg.width - 1, col + kCrfWindowRadius); ++c) {
      const int32_t label = seg.labels[static_cast<size_t>(r) * seg.width + c];
      int j = 0;
      while (j < distinct && labels[j] != label) ++j;
      if (j == distinct) {
        labels[distinct] = label;
        counts[distinct++] = 0;
      }
      ++counts[j];
    }
  }
  const int32_t own = seg.labels[static_cast<size_t>(row) * seg.width + col];
  out[0] = own;
  int n = 1;
  while (n < kMaxCrfLabels) {
    int best = -1;
    for (int j = 0; j < distinct; ++j) {
      if (labels[j] == own || counts[j] < 0) continue;
      if (best < 0 || counts[j] > counts[best] ||
          (counts[j] == counts[best] && labels[j] < labels[best])) {
        best = j;
      }
    }
    if (best < 0) break;
    out[n++] = labels[best];
    counts[best] = -1;  // taken
  }
  return n;
}

ActiveSet FindActivePixels(const Segmentation& seg) {
  const size_t num_pixels = static_cast<size_t>(seg.width) * seg.height;
  // The pixels within the window radius of an edge.
  const std::vector<uint8_t> near_edge =
      DilateMask(seg.edges, seg.width, seg.height, kCrfWindowRadius);
  ActiveSet set;
  set.index.assign(num_pixels, -1);
  int32_t candidates[kMaxCrfLabels];
  for (int row = 0; row < seg.height; ++row) {
    for (int col = 0; col < seg.width; ++col) {
      const size_t i = static_cast<size_t>(row) * seg.width + col;
      if (!near_edge[i]) continue;
      const int n = CollectCandidates(seg, col, row, candidates);
      if (n < 2) continue;
      set.index[i] = static_cast<int>(set.pixel.size());
      set.pixel.push_back(static_cast<int>(i));
      set.count.push_back(static_cast<uint8_t>(n));
      for (int j = 0; j < kMaxCrfLabels; ++j) set.labels.push_back(j < n ? candidates[j] : -1);
    }
  }
  return set;
}

// Unit RGB vectors (the paper's normalised colour I), interleaved per pixel.
std::vector<float> NormalizedColors(const DenseMap& color) {
  const size_t n = static_cast<size_t>(color.width) * color.height;
  std::vector<float> out(3 * n);
  for (size_t i = 0; i < n; ++i) {
    const float r = color.data[i] + kColorEpsilon;
    const float g = color.data[n + i] + kColorEpsilon;
    const float b = color.data[2 * n + i] + kColorEpsilon;
    const float inv = 1.0f / std::sqrt(r * r + g * g + b * b);
    out[3 * i] = r * inv;
    out[3 * i + 1] = g * inv;
    out[3 * i + 2] = b * inv;
  }
  return out;
}

struct CrfImage {
  const Segmentation* seg;
  const ActiveSet* active;
  std::vector<float> rgb;        // normalised colours
  const float* depth = nullptr;  // null: colour only
  float inv_alpha = 0.0f;
  float inv_beta = 0.0f;
};

// exp(-x) for x in [0, kMaxKernelExponent], relative error < 4e-4: the
// kernel is evaluated for every pair in every iteration, where a libm call
// is costly, and mean-field needs no more precision than this.
float ExpNeg(float x) {
  constexpr float kLog2e = 1.44269504f;
  const float y = -x * kLog2e;  // exp(-x) = 2^y, y <= 0
  const float floor_y = std::floor(y);
  const float f = y - floor_y;  // in [0, 1)
  // 2^f on [0, 1): cubic minimax-style fit.
  const float two_f = 1.0f + f * (0.6951786f + f * (0.2261697f + f * 0.0780245f));
  // 2^floor(y) built from its exponent bits (y >= -kMaxKernelExponent * kLog2e > -126).
  const uint32_t bits = static_cast<uint32_t>(static_cast<int>(floor_y) + 127) << 23;
  float scale;
  std::memcpy(&scale, &bits, sizeof(scale));
  return two_f * scale;
}

// Adds k * Q_q(l) to message[j] for every candidate l = labels[j] of p
// (Q_q(l) = 0 for labels q does not hold).
void AddNeighbour(const CrfImage& im, const std::vector<float>& q_values, int q, float k,
                  const int32_t* labels, int n, float* message) {
  const int a = im.active->index[q];
  if (a < 0) {  // single label, Q = 1
    const int32_t label = im.seg->labels[q];
    for (int j = 0; j < n; ++j) {
      if (labels[j] == label) message[j] += k;
    }
    return;
  }
  const int32_t* q_labels = &im.active->labels[static_cast<size_t>(a) * kMaxCrfLabels];
  const float* q_probs = &q_values[static_cast<size_t>(a) * kMaxCrfLabels];
  for (int m = 0; m < im.active->count[a]; ++m) {
    for (int j = 0; j < n; ++j) {
      if (labels[j] == q_labels[m]) message[j] += k * q_probs[m];
    }
  }
}

// Minus the log of the eq. 6 kernel of the pair (p, q) at mean-field iteration t.
float PairExponent(const CrfImage& im, int p, int q, float t) {
  const float* cp = &im.rgb[3 * static_cast<size_t>(p)];
  const float* cq = &im.rgb[3 * static_cast<size_t>(q)];
  const float color_term = std::fabs(cp[0] * cq[0] + cp[1] * cq[1] + cp[2] * cq[2] - 1.0f);
  float exponent = color_term * im.inv_beta / t;
  if (im.depth != nullptr && im.depth[p] > 0.0f && im.depth[q] > 0.0f) {
    exponent += t * std::fabs(im.depth[p] - im.depth[q]) * im.inv_alpha;
  }
  return exponent;
}

// One mean-field update of active pixel `a`: Q_p(l) ~ exp(-U_p(l) - sum_q
// k(p, q) sum_{l' != l} Q_q(l')) = exp(-U_p(l) + sum_q k(p, q) Q_q(l)) up to
// a constant (Potts mu).
void UpdatePixel(const CrfImage& im, const std::vector<float>& unary,
                 const std::vector<float>& q_values, int a, float t, std::vector<float>* next) {
  const Segmentation& seg = *im.seg;
  const int p = im.active->pixel[a];
  const int col = p % seg.width;
  const int row = p / seg.width;
  const int n = im.active->count[a];
  const int32_t* labels = &im.active->labels[static_cast<size_t>(a) * kMaxCrfLabels];
  float message[kMaxCrfLabels] = {0.0f};
  for (int r = std::max(0, row - kCrfWindowRadius);
       r <= std::min(seg.height - 1, row + kCrfWindowRadius); ++r) {
    for (int c = std::max(0, col - kCrfWindowRadius);
         c <= std::min(seg.width - 1, col + kCrfWindowRadius); ++c) {
      const int q = r * seg.width + c;
      if (q == p) continue;
      const float exponent = PairExponent(im, p, q, t);
      if (exponent > kMaxKernelExponent) continue;
      const float k = ExpNeg(exponent);
      AddNeighbour(im, q_values, q, k, labels, n, message);
    }
  }
  float logits[kMaxCrfLabels];
  float max_logit = -INFINITY;
  for (int j = 0; j < n; ++j) {
    logits[j] = -unary[static_cast<size_t>(a) * kMaxCrfLabels + j] + kPairWeight * message[j];
    max_logit = std::max(max_logit, logits[j]);
  }
  float sum = 0.0f;
  for (int j = 0; j < n; ++j) sum += logits[j] = std::exp(logits[j] - max_logit);
  for (int j = 0; j < n; ++j) (*next)[static_cast<size_t>(a) * kMaxCrfLabels + j] = logits[j] / sum;
}

}  // namespace

Segmentation RefineSegmentationCrf(const Segmentation& aggregated, const DenseMap& color,
                                   const DenseMap* depth, float depth_min, float depth_max,
                                   const CrfOptions& options) {
  assert(color.width == aggregated.width && color.height == aggregated.height);
  assert(color.channels == 3);
  const ActiveSet active = FindActivePixels(aggregated);
  CrfImage im;
  im.seg = &aggregated;
  im.active = &active;
  im.rgb = NormalizedColors(color);
  im.inv_beta = 1.0f / options.beta;
  const float alpha = options.alpha_relative * (depth_max - depth_min);
  if (depth != nullptr && !depth->Empty() && alpha > 0.0f) {
    assert(depth->width == aggregated.width && depth->height == aggregated.height);
    im.depth = depth->Plane(0);
    im.inv_alpha = 1.0f / alpha;
  }

  // Unary -ln P(l): the aggregated label has probability unary_confidence,
  // the other candidates share the rest. Q starts at the unary's softmax.
  const int num_active = static_cast<int>(active.pixel.size());
  std::vector<float> unary(static_cast<size_t>(num_active) * kMaxCrfLabels, 0.0f);
  std::vector<float> q_values(unary.size(), 0.0f);
  for (int a = 0; a < num_active; ++a) {
    const int n = active.count[a];
    const float other = (1.0f - options.unary_confidence) / (n - 1);
    for (int j = 0; j < n; ++j) {
      const float p = j == 0 ? options.unary_confidence : other;
      unary[static_cast<size_t>(a) * kMaxCrfLabels + j] = -std::log(p);
      q_values[static_cast<size_t>(a) * kMaxCrfLabels + j] = p;
    }
  }

  std::vector<float> next(q_values.size(), 0.0f);
  const int num_tasks = (num_active + kPixelsPerTask - 1) / kPixelsPerTask;
  for (int iteration = 1; iteration <= options.iterations; ++iteration) {
    const float t = static_cast<float>(iteration);
    ParallelFor(0, num_tasks, options.num_threads, [&](int task) {
      const int end = std::min(num_active, (task + 1) * kPixelsPerTask);
      for (int a = task * kPixelsPerTask; a < end; ++a)
        UpdatePixel(im, unary, q_values, a, t, &next);
    });
    q_values.swap(next);
  }

  Segmentation refined;
  refined.width = aggregated.width;
  refined.height = aggregated.height;
  refined.labels = aggregated.labels;
  for (int a = 0; a < num_active; ++a) {
    const float* q = &q_values[static_cast<size_t>(a) * kMaxCrfLabels];
    int best = 0;
    for (int j = 1; j < active.count[a]; ++j) {
      if (q[j] > q[best]) best = j;
    }
    refined.labels[active.pixel[a]] = active.labels[static_cast<size_t>(a) * kMaxCrfLabels + best];
  }
  refined.edges = ComputeBoundaryMap(refined.labels, refined.width, refined.height);
  return refined;
}

}  // namespace msp
