#pragma once
// JPEG images, which the imagery Debian ships is stored as: decoded by
// stb_image built for JPEG alone, so that no other of its decoders, and
// none of OpenImageIO's less hardened readers, sees a file.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace planet {

struct JpegImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // row 0 at the top
};

// Whether the file begins as a JPEG does.
bool looks_like_jpeg(const std::filesystem::path& file);

// Throws InputError naming the file and `what` it was read as when it is
// not a JPEG stb_image can decode, or is larger than the program reads.
JpegImage read_jpeg_rgba(const std::filesystem::path& file, const char* what);

}  // namespace planet
