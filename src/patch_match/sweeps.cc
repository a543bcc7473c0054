#include "patch_match/sweeps.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/parallel_for.h"

namespace msp {
namespace {

// A depth differing from its 3x3 median by more than this share of it is an outlier.
constexpr float kMedianOutlierRatio = 0.05f;
// The median needs most of the 3x3 neighbourhood to be valid.
constexpr int kMinMedianSamples = 5;

template <typename PixelFn>
void ForEachPixel(const core::PassParams& params, int num_threads, PixelFn fn) {
  const int width = params.state.width;
  ParallelFor(0, params.state.height, num_threads, [&](int row) {
    for (int col = 0; col < width; ++col) fn(col, row);
  });
}

}  // namespace

void InitializeState(const core::PassParams& params, int num_threads) {
  ForEachPixel(params, num_threads,
               [&](int col, int row) { core::InitializePixel(params, col, row); });
  ScoreState(params, num_threads);
}

void ScoreState(const core::PassParams& params, int num_threads) {
  ForEachPixel(params, num_threads, [&](int col, int row) { core::ScorePixel(params, col, row); });
}

void RunCheckerboardIterations(const core::PassParams& params, int num_iterations,
                               int num_threads) {
  const int width = params.state.width;
  for (int iteration = 0; iteration < num_iterations; ++iteration) {
    for (int color = 0; color < 2; ++color) {
      // Pixels of one colour only read pixels of the other: rows are independent.
      ParallelFor(0, params.state.height, num_threads, [&](int row) {
        for (int col = (row + color) & 1; col < width; col += 2) {
          core::UpdatePixel(params, col, row, iteration);
        }
      });
    }
  }
}

void MedianFilterState(const core::PassParams& params, int num_threads) {
  const core::PixelStateView& s = params.state;
  const std::vector<float> depth(s.depth, s.depth + s.width * s.height);
  const std::vector<float> normal(s.normal, s.normal + 3 * s.width * s.height);
  const std::vector<uint32_t> mask(s.mask, s.mask + s.width * s.height);
  const int n = s.width * s.height;
  ForEachPixel(params, num_threads, [&](int col, int row) {
    const int i = s.Index(col, row);
    if (!(depth[i] > 0.0f)) return;
    float values[9];
    int where[9];
    int count = 0;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int c = col + dx, r = row + dy;
        if (c < 0 || r < 0 || c >= s.width || r >= s.height) continue;
        const int q = s.Index(c, r);
        if (!(depth[q] > 0.0f)) continue;
        values[count] = depth[q];
        where[count++] = q;
      }
    }
    if (count < kMinMedianSamples) return;
    float sorted[9];
    std::copy(values, values + count, sorted);
    std::nth_element(sorted, sorted + count / 2, sorted + count);
    const float median = sorted[count / 2];
    if (std::fabs(depth[i] - median) <= kMedianOutlierRatio * median) return;
    const int k = static_cast<int>(std::find(values, values + count, median) - values);
    const int q = where[k];
    const core::PlaneHypothesis hq{depth[q],
                                   core::Vec3{normal[q], normal[n + q], normal[2 * n + q]}};
    const float d =
        core::PropagatedDepth(params.ref_camera, q % s.width, q / s.width, hq, col, row);
    if (!core::DepthInRange(params, d)) return;
    s.Set(i, core::PlaneHypothesis{d, hq.normal});
    s.mask[i] = mask[q];
  });
}

void LocalRefineState(const core::PassParams& params, int num_threads) {
  ForEachPixel(params, num_threads,
               [&](int col, int row) { core::LocalRefinePixel(params, col, row); });
}

void ExtractMaps(const core::PassParams& params, const core::FilterParams* filter, int num_threads,
                 DenseMap* depth, DenseMap* normal, DenseMap* stages) {
  const core::PixelStateView& s = params.state;
  *depth = DenseMap(s.width, s.height, 1);
  *normal = DenseMap(s.width, s.height, 3);
  if (stages != nullptr) *stages = DenseMap(s.width, s.height, 2);
  ForEachPixel(params, num_threads, [&](int col, int row) {
    const int i = s.Index(col, row);
    const core::PlaneHypothesis h = s.Get(i);
    const bool has_plane = h.depth > 0.0f && std::isfinite(h.depth);
    bool kept = has_plane;
    if (stages != nullptr) {
      // FilterStage runs every test of every view, and says kept exactly
      // when the filter's count would. The depth before the filter goes
      // beside the stage, so that the right depth the filter removes can be
      // counted against the ground truth.
      const int stage = !has_plane          ? core::kStageNoPlane
                        : filter != nullptr ? core::FilterStage(params, *filter, col, row)
                                            : core::kStageKept;
      stages->At(row, col, 0) = static_cast<float>(stage);
      stages->At(row, col, 1) = has_plane ? h.depth : 0.0f;
      kept = stage == core::kStageKept;
    } else if (has_plane && filter != nullptr) {
      kept = core::FilterKeeps(params, *filter, col, row);
    }
    if (!kept) return;
    const core::Vec3 n = core::Normalized(core::FaceCamera(params.ref_camera, col, row, h.normal));
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return;
    depth->At(row, col) = h.depth;
    normal->At(row, col, 0) = n.x;
    normal->At(row, col, 1) = n.y;
    normal->At(row, col, 2) = n.z;
  });
}

}  // namespace msp
