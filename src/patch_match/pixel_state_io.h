// One image's PixelState as bytes: what the state cache spills and what the
// shards of a run exchange between passes. The bytes hold every plane of the
// state bit for bit, so a state read back continues exactly as the one kept
// in memory would have.
#pragma once

#include <string>

#include "engine/pixel_state.h"

namespace msp {

std::string SerializePixelState(const PixelState& state);

// False (leaving `state` unspecified) when `bytes` are not a whole state:
// another format, a size that does not match the header, or truncated.
bool DeserializePixelState(const std::string& bytes, PixelState* state);

}  // namespace msp
