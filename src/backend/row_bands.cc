#include "backend/row_bands.h"

#include <sstream>
#include <stdexcept>

namespace msp {

std::vector<RowBand> PlanRowBands(const std::vector<size_t>& row_bytes, size_t budget) {
  std::vector<RowBand> bands;
  const int rows = static_cast<int>(row_bytes.size());
  size_t used = 0;
  for (int row = 0; row < rows; ++row) {
    if (row_bytes[row] > budget) {
      std::ostringstream msg;
      msg << "row " << row << " needs " << row_bytes[row]
          << " bytes of device memory, more than the " << budget
          << " bytes free for a band of rows";
      throw std::runtime_error(msg.str());
    }
    if (bands.empty() || used + row_bytes[row] > budget) {
      bands.push_back({row, row});
      used = 0;
    }
    used += row_bytes[row];
    bands.back().end = row + 1;
  }
  return bands;
}

}  // namespace msp
