#pragma once
// JPEG images, which the imagery Debian ships is stored as: decoded by
// libjpeg-turbo directly (OpenImageIO's JPEG reader stays refused: see
// core/image_io.h), with its errors turned into InputError.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace planet {

struct JpegImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // row 0 at the top, alpha 255
};

// Whether the file begins as a JPEG does.
bool looks_like_jpeg(const std::filesystem::path& file);

// Throws InputError naming the file and `what` it was read as when it is
// not a JPEG libjpeg can decode, is larger than the program reads, or
// holds more scans than any real image (a progressive file of thousands
// of scans would take minutes).
JpegImage read_jpeg_rgba(const std::filesystem::path& file, const char* what);

}  // namespace planet
