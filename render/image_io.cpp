#include "render/image_io.h"

#include "sim/error.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <fstream>

namespace planet {

namespace {

template <typename T>
void write_rgb(const std::filesystem::path& file, int width, int height,
               const std::vector<T>& rgba, OIIO::TypeDesc type) {
  std::vector<T> rgb(size_t(width) * size_t(height) * 3);
  for (int y = 0; y < height; ++y) {
    const T* src = rgba.data() + size_t(height - 1 - y) * size_t(width) * 4;
    T* dst = rgb.data() + size_t(y) * size_t(width) * 3;
    for (int x = 0; x < width; ++x) {
      dst[3 * x + 0] = src[4 * x + 0];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
  // OIIO picks the format from the extension, so the temporary keeps it.
  std::filesystem::path partial = file.parent_path() / (".partial-" + file.filename().string());
  auto out = OIIO::ImageOutput::create(partial.string());
  if (!out) throw SystemError(fmt::format("{}: {}", file.string(), OIIO::geterror()));
  OIIO::ImageSpec spec(width, height, 3, type);
  if (type == OIIO::TypeDesc::FLOAT) spec.attribute("compression", "zip");
  // OpenEXR files otherwise get the wall-clock time (capDate), and the same
  // capture must give the same bytes.
  spec.attribute("DateTime", "2000:01:01 00:00:00");
  if (!out->open(partial.string(), spec) || !out->write_image(type, rgb.data()) ||
      !out->close()) {
    std::string error = out->geterror();
    std::filesystem::remove(partial);
    throw SystemError(fmt::format("{}: cannot write: {}", file.string(), error));
  }
  std::filesystem::rename(partial, file);
}

}  // namespace

void write_exr(const std::filesystem::path& file, int width, int height,
               const std::vector<float>& rgba) {
  write_rgb(file, width, height, rgba, OIIO::TypeDesc::FLOAT);
}

void write_png(const std::filesystem::path& file, int width, int height,
               const std::vector<uint8_t>& rgba) {
  write_rgb(file, width, height, rgba, OIIO::TypeDesc::UINT8);
}

ImageRGB read_image_rgb(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw InputError(fmt::format("{}: cannot read image: {}", file.string(), OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3) {
    throw InputError(fmt::format("{}: {} channels, need at least RGB", file.string(), spec.nchannels));
  }
  ImageRGB image;
  image.width = spec.width;
  image.height = spec.height;
  image.pixels.resize(size_t(spec.width) * size_t(spec.height) * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    throw InputError(fmt::format("{}: cannot read image: {}", file.string(), in->geterror()));
  }
  return image;
}

void write_text_file(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::path partial = file.parent_path() / (".partial-" + file.filename().string());
  {
    std::ofstream out(partial);
    out << text;
    if (!out) throw SystemError(fmt::format("{}: cannot write", file.string()));
  }
  std::filesystem::rename(partial, file);
}

}  // namespace planet
