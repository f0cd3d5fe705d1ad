#include "core/image_io.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

namespace planet {

namespace {

// `rgb` holds RGB rows top-down.
template <typename T>
void write_rgb(const std::filesystem::path& file, int width, int height, const std::vector<T>& rgb,
               OIIO::TypeDesc type) {
  // OIIO picks the format from the extension, so the temporary keeps it.
  std::filesystem::path partial = partial_file(file);
  auto out = OIIO::ImageOutput::create(partial.string());
  if (!out) throw SystemError(fmt::format("{}: {}", file.string(), OIIO::geterror()));
  OIIO::ImageSpec spec(width, height, 3, type);
  if (type == OIIO::TypeDesc::FLOAT) spec.attribute("compression", "zip");
  // OpenEXR files otherwise get the wall-clock time (capDate), and the same
  // capture must give the same bytes.
  spec.attribute("DateTime", "2000:01:01 00:00:00");
  if (!out->open(partial.string(), spec) || !out->write_image(type, rgb.data()) || !out->close()) {
    std::string error = out->geterror();
    std::filesystem::remove(partial);
    throw SystemError(fmt::format("{}: cannot write: {}", file.string(), error));
  }
  std::filesystem::rename(partial, file);
}

}  // namespace

void write_exr(const std::filesystem::path& file, const ImageRGB& image) {
  write_rgb(file, image.width, image.height, image.pixels, OIIO::TypeDesc::FLOAT);
}

void write_exr(const std::filesystem::path& file, int width, int height,
               const std::vector<float>& rgba) {
  write_rgb(file, width, height, rgb_rows_from_gl(width, height, rgba), OIIO::TypeDesc::FLOAT);
}

void write_png_rgb8(const std::filesystem::path& file, int width, int height,
                    const std::vector<uint8_t>& rgb) {
  write_rgb(file, width, height, rgb, OIIO::TypeDesc::UINT8);
}

void write_png(const std::filesystem::path& file, int width, int height,
               const std::vector<uint8_t>& rgba) {
  write_png_rgb8(file, width, height, rgb_rows_from_gl(width, height, rgba));
}

ImageRGB read_image_rgb(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in)
    throw InputError(fmt::format("{}: cannot read image: {}", file.string(), OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3) {
    throw InputError(
        fmt::format("{}: {} channels, need at least RGB", file.string(), spec.nchannels));
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

}  // namespace planet
