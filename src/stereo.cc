#include "stereo.h"

#include <stdexcept>

namespace msp {

void RunStereo(const std::vector<View>&, const std::vector<Problem>&,
               const PatchMatchStereoOptions&, const MspStereoOptions&, const std::string&,
               MapSink&) {
  throw std::runtime_error(
      "no stereo back-end yet: this build of msp_stereo reads and checks the workspace but "
      "cannot compute depth maps");
}

}  // namespace msp
