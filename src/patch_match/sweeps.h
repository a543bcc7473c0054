// Whole-image steps of one pass on the CPU, each parallel over rows.
#pragma once

#include "base/dense_map.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/output_filter.h"
#include "core/patch_match/patch_match_kernel.h"
#include "engine/pixel_state.h"

namespace msp {

// Random planes for every pixel, then their costs.
void InitializeState(const core::PassParams& params, int num_threads);
// Recomputes every pixel's stored cost under the pass's cost function.
void ScoreState(const core::PassParams& params, int num_threads);
// `num_iterations` red-black checkerboard iterations (red pixels, barrier, black).
void RunCheckerboardIterations(const core::PassParams& params, int num_iterations, int num_threads);
// Replaces planes whose depth is an outlier in its 3x3 neighbourhood by the
// plane of the neighbour holding the median depth.
void MedianFilterState(const core::PassParams& params, int num_threads);
// The +-5 px disparity sweep with fixed normals.
void LocalRefineState(const core::PassParams& params, int num_threads);
// Depth and normal maps of the state; with `filter`, only pixels with enough
// consistent views keep their depth (the rest are 0). With `stages`, also
// where each pixel's depth goes (2 channels: its core::MapStage and its depth
// before the filter, 0 without a plane), for --MspStereo.write_previews.
void ExtractMaps(const core::PassParams& params, const core::FilterParams* filter, int num_threads,
                 DenseMap* depth, DenseMap* normal, DenseMap* stages = nullptr);

}  // namespace msp
