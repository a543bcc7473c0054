// The format and size a workspace image declares in its header, read before
// the file is decoded, for the reason png_header.h gives: a decoder allocates
// what the header declares, so a corrupt or foreign header could ask for
// gigabytes. The formats are those COLMAP workspaces hold (COLMAP's
// image_undistorter keeps the input images' format); a file of any other
// format is never handed to a decoder, since some of OpenCV's (DICOM, for
// one) abort the process on a malformed file instead of failing.
#pragma once

#include <cstdint>
#include <string>

namespace msp {

enum class ImageFormat { kUnknown, kPng, kJpeg, kTiff, kBmp };

// "PNG", "JPEG", "TIFF", "BMP" or "unknown".
const char* ImageFormatName(ImageFormat format);

// The format the first bytes of `path` announce (its signature, whatever its
// name); kUnknown when it cannot be read or announces none of the above.
ImageFormat DetectImageFormat(const std::string& path);

// The width and height the header of `path`, a file of `format`, declares:
// PNG's IHDR chunk, the first JPEG start-of-frame marker, the first TIFF
// image file directory (classic or BigTIFF), BMP's info header. False when
// the header is missing, cut short or malformed.
bool ReadImageSize(const std::string& path, ImageFormat format, uint32_t* width, uint32_t* height);

}  // namespace msp
