#include "patch_match/unlit_pixels.h"

#include <algorithm>

#include "base/dilate_mask.h"

namespace msp {

std::vector<uint8_t> UnlitPixels(const DenseMap& gray, int radius, float black_level) {
  if (!(black_level > 0.0f)) return {};
  // A window is lit when one of its pixels is: the lit pixels dilated.
  std::vector<uint8_t> lit(gray.data.size());
  for (size_t i = 0; i < lit.size(); ++i) lit[i] = gray.data[i] >= black_level ? 1 : 0;
  std::vector<uint8_t> unlit = DilateMask(lit, gray.width, gray.height, radius);
  for (uint8_t& u : unlit) u = 1 - u;
  if (std::find(unlit.begin(), unlit.end(), 1) == unlit.end()) return {};
  return unlit;
}

}  // namespace msp
