#include "terrain/jpeg_image.h"

#include "core/error.h"
#include "core/image_io.h"
#include "core/paths.h"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <memory>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO_WRITE
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>

namespace planet {

bool looks_like_jpeg(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char b[3] = {0, 0, 0};
  in.read(reinterpret_cast<char*>(b), 3);
  return in.gcount() == 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF;
}

JpegImage read_jpeg_rgba(const std::filesystem::path& file, const char* what) {
  check_readable_file(file);
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(fmt::format("{}: cannot open {}", file.string(), what));
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_file(f.get(), &w, &h, &n)) {
    throw InputError(
        fmt::format("{}: not a JPEG image ({}): {}", file.string(), what, stbi_failure_reason()));
  }
  check_image_size(file, what, w, h, 4);
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_file(f.get(), &w, &h, &n, 4),
                                                   &stbi_image_free);
  if (!pixels) {
    throw InputError(
        fmt::format("{}: cannot decode {}: {}", file.string(), what, stbi_failure_reason()));
  }
  JpegImage out{w, h, {}};
  out.rgba.assign(pixels.get(), pixels.get() + size_t(w) * size_t(h) * 4);
  return out;
}

}  // namespace planet
