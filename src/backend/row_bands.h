// Row bands of a reference image for the CUDA back-end's deformable step:
// when the anchors of every unreliable pixel do not fit in the GPU's free
// memory at once, they are kept on the host and brought to the device one
// band of rows at a time. No halo is needed: a band's kernels read only
// their own pixels' anchors, and everything they read of other pixels (the
// planes, their snapshot, the classes, the nearest reliable pixels) stays
// on the device whole, so the banded run equals the unbanded one exactly.
#pragma once

#include <cstddef>
#include <vector>

namespace msp {

struct RowBand {
  int begin = 0;  // first row
  int end = 0;    // one past the last row
};

// Consecutive bands covering rows 0 .. row_bytes.size() - 1, each with as
// many rows as fit in `budget` bytes (row r needs row_bytes[r]), so the
// fewest bands result. An image that fits whole is one band; no rows, no
// band. Throws std::runtime_error naming the row, its bytes and the budget
// when one row alone does not fit.
std::vector<RowBand> PlanRowBands(const std::vector<size_t>& row_bytes, size_t budget);

}  // namespace msp
