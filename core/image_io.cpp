#include "core/image_io.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <fstream>

namespace planet {

namespace {

void add_attribute(OIIO::ImageSpec& spec, const ImageAttribute& a) {
  if (const double* d = std::get_if<double>(&a.value)) {
    spec.attribute(a.name, OIIO::TypeDesc::DOUBLE, d);
  } else if (const float* f = std::get_if<float>(&a.value)) {
    spec.attribute(a.name, *f);
  } else if (const std::string* s = std::get_if<std::string>(&a.value)) {
    spec.attribute(a.name, *s);
  } else if (const glm::dvec3* v = std::get_if<glm::dvec3>(&a.value)) {
    spec.attribute(a.name, OIIO::TypeDesc(OIIO::TypeDesc::DOUBLE, OIIO::TypeDesc::VEC3), v);
  } else {
    // GLM stores columns one after the other: the rows of the transpose,
    // which is the row-vector matrix OpenEXR (Imath) stores.
    spec.attribute(a.name, OIIO::TypeMatrix44, &std::get<glm::mat4>(a.value)[0][0]);
  }
}

// `pixels` holds `channels` values a pixel, rows top-down.
template <typename T>
void write_image(const std::filesystem::path& file, int width, int height, int channels,
                 const std::vector<T>& pixels, OIIO::TypeDesc type, const ExrExtras& extras = {}) {
  // OIIO picks the format from the extension, so the temporary keeps it.
  std::filesystem::path partial = partial_file(file);
  auto out = OIIO::ImageOutput::create(partial.string());
  if (!out) throw SystemError(fmt::format("{}: {}", file.string(), OIIO::geterror()));
  OIIO::ImageSpec spec(width, height, channels, type);
  if (channels == 4) {
    spec.channelnames = {"R", "G", "B", "Z"};
    spec.z_channel = 3;
  }
  if (type == OIIO::TypeDesc::FLOAT) spec.attribute("compression", "zip");
  // OpenEXR files otherwise get the wall-clock time (capDate), and the same
  // capture must give the same bytes.
  spec.attribute("DateTime", "2000:01:01 00:00:00");
  for (const ImageAttribute& a : extras.attributes) add_attribute(spec, a);
  if (!out->open(partial.string(), spec) || !out->write_image(type, pixels.data()) ||
      !out->close()) {
    std::string error = out->geterror();
    std::filesystem::remove(partial);
    throw SystemError(fmt::format("{}: cannot write: {}", file.string(), error));
  }
  std::filesystem::rename(partial, file);
}

}  // namespace

void write_exr(const std::filesystem::path& file, const ImageRGB& image) {
  write_image(file, image.width, image.height, 3, image.pixels, OIIO::TypeDesc::FLOAT);
}

void write_exr(const std::filesystem::path& file, int width, int height,
               const std::vector<float>& rgba, const ExrExtras& extras) {
  std::vector<float> rgb = rgb_rows_from_gl(width, height, rgba);
  if (extras.depth.empty()) {
    write_image(file, width, height, 3, rgb, OIIO::TypeDesc::FLOAT, extras);
    return;
  }
  std::vector<float> rgbz(size_t(width) * size_t(height) * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      size_t i = size_t(y) * size_t(width) + size_t(x);
      for (size_t c = 0; c < 3; ++c) rgbz[4 * i + c] = rgb[3 * i + c];
      // GL's rows bottom-up, as the colour came.
      rgbz[4 * i + 3] = extras.depth[size_t(height - 1 - y) * size_t(width) + size_t(x)];
    }
  }
  write_image(file, width, height, 4, rgbz, OIIO::TypeDesc::FLOAT, extras);
}

void write_png_rgb8(const std::filesystem::path& file, int width, int height,
                    const std::vector<uint8_t>& rgb) {
  write_image(file, width, height, 3, rgb, OIIO::TypeDesc::UINT8);
}

void write_png(const std::filesystem::path& file, int width, int height,
               const std::vector<uint8_t>& rgba) {
  write_png_rgb8(file, width, height, rgb_rows_from_gl(width, height, rgba));
}

void check_image_signature(const std::filesystem::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  char b[4] = {0, 0, 0, 0};
  in.read(b, 4);
  auto is = [&](const char* magic, size_t n) { return in.gcount() >= std::streamsize(n) && std::equal(b, b + n, magic); };
  bool known = is("\x89PNG", 4) || is("II*\0", 4) || is("MM\0*", 4) || is("v/1\x01", 4) ||
               (in.gcount() >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6');
  if (!known) {
    throw InputError(fmt::format("{}: not a PNG, TIFF, OpenEXR or PNM image (by its first bytes); "
                                 "{} reads only those",
                                 file.string(), what));
  }
}

void check_image_size(const std::filesystem::path& file, const std::string& what, long long width,
                      long long height, long long channels) {
  if (width < 1 || height < 1 || channels < 1) {
    throw InputError(fmt::format("{}: {} with no pixels ({}x{}, {} channels)", file.string(), what,
                                 width, height, channels));
  }
  if (width > kMaxImageValues || height > kMaxImageValues / width ||
      channels > kMaxImageValues / (width * height)) {
    throw InputError(fmt::format(
        "{}: {} of {}x{} pixels and {} channels is larger than the {} values the program reads",
        file.string(), what, width, height, channels, kMaxImageValues));
  }
}

ImageRGB read_image_rgb(const std::filesystem::path& file) {
  check_image_signature(file, "an image of the program's");
  auto in = OIIO::ImageInput::open(file.string());
  if (!in)
    throw InputError(fmt::format("{}: cannot read image: {}", file.string(), OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  check_image_size(file, "an image of the program's", spec.width, spec.height, spec.nchannels);
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
