// The size a PNG file declares in its header (IHDR, the first chunk), read
// before the file is decoded: the decoder allocates what the header declares,
// so a corrupt or foreign header could otherwise ask for gigabytes. The
// readers of user PNGs (workspace images, mask layers, sensor depth maps)
// check it against the size they expect first.
#pragma once

#include <cstdint>
#include <string>

namespace msp {

// True when `path` starts with the 8-byte PNG signature, whatever follows.
bool HasPngSignature(const std::string& path);

// False when `path` cannot be read or does not start with a PNG signature and
// an IHDR chunk; otherwise the declared width and height.
bool ReadPngSize(const std::string& path, uint32_t* width, uint32_t* height);

}  // namespace msp
