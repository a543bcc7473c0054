#include "base/nearest_marked_pixels.h"

#include <limits>

#include "base/parallel_for.h"
#include "core/deformable/deformable_limits.h"

namespace msp {
namespace {

constexpr int kNone = -1;

// Lower envelope of the parabolas (x - q)^2 + f[q] over the columns q with a
// feature (row_of[q] >= 0); writes to nearest[x] the feature index minimising
// the squared distance from (x, row). One row of the second pass.
void EnvelopeRow(const int* row_of, int width, int row, int* nearest, std::vector<int>& v,
                 std::vector<double>& z) {
  auto f = [&](int q) {
    const double d = static_cast<double>(row_of[q] - row);
    return d * d;
  };
  int k = -1;  // index of the rightmost parabola of the envelope
  for (int q = 0; q < width; ++q) {
    if (row_of[q] == kNone) continue;
    double s = -std::numeric_limits<double>::infinity();
    while (k >= 0) {
      const int p = v[k];
      // Abscissa where parabolas p and q intersect.
      s = ((f(q) + static_cast<double>(q) * q) - (f(p) + static_cast<double>(p) * p)) /
          (2.0 * (q - p));
      if (s > z[k]) break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -std::numeric_limits<double>::infinity() : s;
  }
  if (k < 0) {
    for (int x = 0; x < width; ++x) nearest[x] = kNone;
    return;
  }
  int j = 0;
  for (int x = 0; x < width; ++x) {
    while (j < k && z[j + 1] < x) ++j;
    nearest[x] = row_of[v[j]] * width + v[j];
  }
}

// The nearest pixel i with is_feature(i), for every pixel.
template <typename IsFeature>
std::vector<int> NearestFeaturePixels(IsFeature is_feature, int width, int height,
                                      int num_threads) {
  const size_t n = static_cast<size_t>(width) * height;
  // First pass, per column: the row of the nearest feature pixel in the column.
  std::vector<int> column_row(n, kNone);
  ParallelFor(0, width, num_threads, [&](int col) {
    int last = kNone;
    for (int row = 0; row < height; ++row) {
      if (is_feature(static_cast<size_t>(row) * width + col)) last = row;
      column_row[static_cast<size_t>(row) * width + col] = last;
    }
    last = kNone;
    for (int row = height - 1; row >= 0; --row) {
      const size_t i = static_cast<size_t>(row) * width + col;
      if (is_feature(i)) last = row;
      if (last != kNone && (column_row[i] == kNone || last - row < row - column_row[i])) {
        column_row[i] = last;
      }
    }
  });
  // Second pass, per row: the exact 2D nearest over all columns.
  std::vector<int> nearest(n, kNone);
  ParallelFor(0, height, num_threads, [&](int row) {
    std::vector<int> v(width);
    std::vector<double> z(width);
    EnvelopeRow(column_row.data() + static_cast<size_t>(row) * width, width, row,
                nearest.data() + static_cast<size_t>(row) * width, v, z);
  });
  return nearest;
}

}  // namespace

std::vector<int> NearestReliablePixels(const uint8_t* classes, int width, int height,
                                       int num_threads) {
  return NearestFeaturePixels([classes](size_t i) { return classes[i] == core::kReliable; }, width,
                              height, num_threads);
}

std::vector<int> NearestMarkedPixels(const uint8_t* marks, int width, int height, int num_threads) {
  return NearestFeaturePixels([marks](size_t i) { return marks[i] != 0; }, width, height,
                              num_threads);
}

}  // namespace msp
