#include "terrain/jpeg_image.h"

#include "core/error.h"
#include "core/image_io.h"
#include "core/paths.h"

#include <fmt/format.h>

#include <csetjmp>
#include <cstdio>
#include <fstream>
#include <memory>

#include <jpeglib.h>

namespace planet {

namespace {

// A progressive JPEG has about ten scans; hundreds mean a crafted file.
constexpr int kMaxScans = 200;

// libjpeg's errors leave through longjmp back into read_jpeg_rgba, with
// its message kept, rather than its default exit().
struct ErrorManager {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr info) {
  auto* e = reinterpret_cast<ErrorManager*>(info->err);
  (*info->err->format_message)(info, e->message);
  std::longjmp(e->jump, 1);
}

// libjpeg goes on past corrupt or truncated data with a warning (level
// -1), filling in grey; an image half read is an error here.
void on_message(j_common_ptr info, int level) {
  if (level >= 0) return;  // trace messages
  on_error(info);
}

void on_progress(j_common_ptr info) {
  auto* d = reinterpret_cast<j_decompress_ptr>(info);
  if (d->input_scan_number > kMaxScans) {
    auto* e = reinterpret_cast<ErrorManager*>(info->err);
    std::snprintf(e->message, sizeof e->message, "more than %d scans", kMaxScans);
    std::longjmp(e->jump, 1);
  }
}

}  // namespace

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

  // Everything the jump can cross is declared before it and is plain data
  // or owned outside the jump's reach.
  JpegImage out;
  jpeg_decompress_struct info{};
  ErrorManager errors{};
  jpeg_progress_mgr progress{};
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = on_error;
  errors.base.emit_message = on_message;
  progress.progress_monitor = on_progress;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    throw InputError(
        fmt::format("{}: cannot decode {} as JPEG: {}", file.string(), what, errors.message));
  }
  jpeg_create_decompress(&info);
  info.progress = &progress;
  jpeg_stdio_src(&info, f.get());
  jpeg_read_header(&info, TRUE);
  try {
    check_image_size(file, what, info.image_width, info.image_height, 4);
  } catch (const InputError&) {
    jpeg_destroy_decompress(&info);
    throw;
  }
  info.out_color_space = JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  out.width = int(info.output_width);
  out.height = int(info.output_height);
  out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out.rgba.data() + size_t(info.output_scanline) * size_t(out.width) * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return out;
}

}  // namespace planet
