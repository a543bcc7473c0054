#include "base/label_layers.h"

#include <cassert>

namespace msp {
namespace {

// Source index of output index i for a resize from `from` to `to` samples.
int NearestSource(int i, int from, int to) {
  const int source = static_cast<int>((2 * static_cast<int64_t>(i) + 1) * from / (2 * to));
  return source < from ? source : from - 1;
}

}  // namespace

std::vector<int32_t> ResampleLabelsNearest(const std::vector<int32_t>& labels, int width,
                                           int height, int new_width, int new_height) {
  assert(labels.size() == static_cast<size_t>(width) * height);
  if (new_width == width && new_height == height) return labels;
  std::vector<int> source_cols(new_width);
  for (int col = 0; col < new_width; ++col) source_cols[col] = NearestSource(col, width, new_width);
  std::vector<int32_t> out(static_cast<size_t>(new_width) * new_height);
  for (int row = 0; row < new_height; ++row) {
    const int32_t* src =
        labels.data() + static_cast<size_t>(NearestSource(row, height, new_height)) * width;
    int32_t* dst = out.data() + static_cast<size_t>(row) * new_width;
    for (int col = 0; col < new_width; ++col) dst[col] = src[source_cols[col]];
  }
  return out;
}

LabelLayers ResampleNearest(const LabelLayers& layers, int new_width, int new_height) {
  LabelLayers out;
  out.width = new_width;
  out.height = new_height;
  out.levels.reserve(layers.levels.size());
  for (const std::vector<int32_t>& level : layers.levels) {
    out.levels.push_back(
        ResampleLabelsNearest(level, layers.width, layers.height, new_width, new_height));
  }
  return out;
}

}  // namespace msp
