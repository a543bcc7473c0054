// Pictures for people (the previews of --MspStereo.write_previews): an 8-bit
// RGB image type, the folder the previews share and their PNG writer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace msp {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
  bool operator!=(const Rgb& o) const { return !(*this == o); }
};

// Row-major pixels; a new image is black.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;

  RgbImage(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h) {}
  Rgb& At(int row, int col) { return pixels[static_cast<size_t>(row) * width + col]; }
  const Rgb& At(int row, int col) const { return pixels[static_cast<size_t>(row) * width + col]; }
};

// A fraction in [0, 1] as a byte, rounded; clamped outside.
uint8_t ToByte(float fraction);

// <workspace>/stereo/prior_previews/<image_name><suffix>: every preview of an
// image lies next to its prior preview, so one folder holds all the pictures.
std::string PreviewPath(const std::string& workspace_path, const std::string& image_name,
                        const std::string& suffix);

// Writes `image` as a PNG under a temporary name and renames it (creating
// missing folders); throws InputError naming `path`.
void WritePreviewPng(const std::string& path, const RgbImage& image);

}  // namespace msp
