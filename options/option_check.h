// Validation of the msp_stereo options. The ranges are COLMAP's
// (PatchMatchOptions::Check in 3.8) except where our code is narrower, which
// is then said in the message (window_radius, see kMaxWindowRadius).
#pragma once

#include "options/option_parser.h"
#include "options/stereo_options.h"

namespace msp {

// Each throws OptionError on the first invalid value; the message names the
// option as given on the command line (spelt from the field, option_name.h),
// the bad value and the allowed range, e.g.
// "invalid value 3 for --PatchMatchStereo.window_step: must be in [1, 2]".
void CheckPatchMatchStereoOptions(const PatchMatchStereoOptions& options);
void CheckMspStereoOptions(const MspStereoOptions& options);
// The workspace fields plus both structs above.
void CheckStereoCommandOptions(const StereoCommandOptions& options);

}  // namespace msp
