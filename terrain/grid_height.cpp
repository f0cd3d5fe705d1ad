#include "terrain/grid_height.h"

#include "core/error.h"
#include "core/image_io.h"
#include "core/paths.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace planet {

namespace {

constexpr double kPi = glm::pi<double>();

// Catmull-Rom's weights for the four samples around a fraction t in [0, 1).
void catmull_rom(double t, double w[4]) {
  double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t + 2.0 * t2 - t3);
  w[1] = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  w[2] = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  w[3] = 0.5 * (-t2 + t3);
}

double smoothstep01(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// Catmull-Rom leaves the range of the two samples it runs between by at
// most 1/8 of its outer neighbours' steps (its negative weights -t(1-t)^2/2
// and -t^2(1-t)/2 sum to at most 1/8); done along rows and then along a
// column, at most 0.28 of the largest step between neighbours.
constexpr double kOvershoot = 0.3;

// Rows of samples per radian of latitude and the blend width at a pole, in rows.
double rows_per_radian(const GridSpec& s) {
  return s.registration == GridSpec::Registration::kPixel ? s.height / kPi : (s.height - 1) / kPi;
}
double pole_blend_rows(const GridSpec& s) {
  return s.registration == GridSpec::Registration::kPixel ? 0.5 : 1.0;
}
// Latitude of row j's centre, radians.
double row_latitude(const GridSpec& s, int j) {
  double offset = s.registration == GridSpec::Registration::kPixel ? 0.5 : 0.0;
  return 0.5 * kPi - (j + offset) / rows_per_radian(s);
}

}  // namespace

GridData::GridData(const GridSpec& spec) : spec_(spec), scale_(spec.scale), offset_(spec.offset) {
  const std::string name = spec_.file.string();
  int min_rows = spec_.registration == GridSpec::Registration::kNode ? 3 : 2;
  if (spec_.width < 4 || spec_.width % 2 != 0 || spec_.height < min_rows ||
      double(spec_.width) * double(spec_.height) > double(kMaxImageValues)) {
    throw InputError(fmt::format(
        "{}: a grid of {} x {} samples cannot be a global elevation grid (it needs an even "
        "width of 4 or more, {} rows or more, at most {} samples)",
        name, spec_.width, spec_.height, min_rows, kMaxImageValues));
  }
  check_readable_file(spec_.file);
  if (spec_.layout == GridSpec::Layout::kPngU16)
    read_png();
  else
    read_raw();
  check_and_summarise();
}

void GridData::read_raw() {
  const std::string name = spec_.file.string();
  size_t count = size_t(spec_.width) * size_t(spec_.height);
  std::error_code ec;
  uintmax_t bytes = std::filesystem::file_size(spec_.file, ec);
  if (ec) throw InputError(fmt::format("{}: cannot read its size: {}", name, ec.message()));
  if (bytes != 2 * count) {
    throw InputError(fmt::format(
        "{}: {} bytes, but a grid of {} x {} 16-bit samples is {} bytes ({})", name, bytes,
        spec_.width, spec_.height, 2 * count, bytes < 2 * count ? "truncated?" : "not this grid?"));
  }
  std::vector<unsigned char> raw(2 * count);
  std::ifstream in(spec_.file, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(raw.size()))) {
    throw InputError(fmt::format("{}: cannot read its {} bytes", name, raw.size()));
  }
  codes_.resize(count);
  bool little = spec_.layout == GridSpec::Layout::kInt16Le;
  for (size_t k = 0; k < count; ++k) {
    unsigned lo = raw[2 * k + (little ? 0 : 1)], hi = raw[2 * k + (little ? 1 : 0)];
    codes_[k] = int16_t(uint16_t(lo | (hi << 8)));
  }
}

void GridData::read_png() {
  const std::string name = spec_.file.string();
  check_image_signature(spec_.file, "an elevation grid");
  auto in = OIIO::ImageInput::open(name);
  if (!in)
    throw InputError(fmt::format("{}: cannot read elevation grid: {}", name, OIIO::geterror()));
  const OIIO::ImageSpec& s = in->spec();
  check_image_size(spec_.file, "an elevation grid", s.width, s.height, s.nchannels);
  if (s.width != spec_.width || s.height != spec_.height || s.nchannels != 1 ||
      s.format != OIIO::TypeDesc::UINT16) {
    throw InputError(fmt::format(
        "{}: an image of {} x {} pixels, {} channel(s) of {}, where the body's file declares "
        "{} x {} of one 16-bit channel",
        name, s.width, s.height, s.nchannels, s.format.c_str(), spec_.width, spec_.height));
  }
  size_t count = size_t(spec_.width) * size_t(spec_.height);
  std::vector<uint16_t> values(count);
  if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT16, values.data())) {
    throw InputError(
        fmt::format("{}: cannot read elevation grid pixels: {}", name, in->geterror()));
  }
  // Unsigned values v keep their meaning as codes v - 32768 with the
  // offset moved by as much.
  codes_.resize(count);
  for (size_t k = 0; k < count; ++k) codes_[k] = int16_t(int(values[k]) - 32768);
  offset_ = spec_.offset + 32768.0 * spec_.scale;
}

double GridData::sample(int i, int j) const {
  const int w = spec_.width, h = spec_.height;
  bool pixel = spec_.registration == GridSpec::Registration::kPixel;
  if (j < 0) {
    j = pixel ? -j - 1 : -j;
    i += w / 2;
  } else if (j > h - 1) {
    j = pixel ? 2 * h - 1 - j : 2 * (h - 1) - j;
    i += w / 2;
  }
  j = std::clamp(j, 0, h - 1);
  i = ((i % w) + w) % w;
  return codes_[size_t(j) * size_t(w) + size_t(i)] * scale_ + offset_;
}

void GridData::check_and_summarise() {
  const std::string name = spec_.file.string();
  const int w = spec_.width, h = spec_.height;
  range_ = {1e300, -1e300};
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      double v = sample(i, j);
      if (!std::isfinite(v) || std::abs(v) > kMaxGridHeight) {
        throw InputError(fmt::format(
            "{}: the sample at row {}, column {} is {} m, not a height (beyond +-{:.0f} km; a "
            "missing-data value, or the wrong byte order or scale?)",
            name, j, i, v, kMaxGridHeight / 1e3));
      }
      range_.min = std::min(range_.min, v);
      range_.max = std::max(range_.max, v);
    }
  }
  // The poles' values and the steepest steps, in metres per radian of arc.
  for (int pole = 0; pole < 2; ++pole) {
    int j = pole == 0 ? 0 : h - 1;
    double sum = 0;
    for (int i = 0; i < w; ++i) sum += sample(i, j);
    pole_[pole] = sum / w;
  }
  double dlat = 1.0 / rows_per_radian(spec_), dlon = 2.0 * kPi / w;
  double blend = pole_blend_rows(spec_) * dlat;
  for (int j = 0; j < h; ++j) {
    double arc_east = std::cos(row_latitude(spec_, j)) * dlon;
    for (int i = 0; i < w; ++i) {
      double v = sample(i, j);
      double east = std::abs(sample(i + 1, j) - v), south = std::abs(sample(i, j + 1) - v);
      max_step_ = std::max({max_step_, east, south});
      if (arc_east > 1e-9) max_slope_ = std::max(max_slope_, east / arc_east);
      if (j < h - 1) max_slope_ = std::max(max_slope_, south / dlat);
      // The pole's blend: from the pole's value to the ring's within `blend`,
      // at up to 1.5 times the mean rate (smoothstep's steepest).
      if (j == 0 || j == h - 1) {
        double step = std::abs(v - pole_[j == 0 ? 0 : 1]);
        max_step_ = std::max(max_step_, step);
        max_slope_ = std::max(max_slope_, 1.5 * step / blend);
      }
    }
  }
  // The min-max pyramid, from blocks of kBlock x kBlock samples.
  Level level;
  level.width = (w + kBlock - 1) / kBlock;
  level.height = (h + kBlock - 1) / kBlock;
  level.min.assign(size_t(level.width) * size_t(level.height), 1e30f);
  level.max.assign(level.min.size(), -1e30f);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      size_t k = size_t(j / kBlock) * size_t(level.width) + size_t(i / kBlock);
      float v = float(sample(i, j));
      level.min[k] = std::min(level.min[k], v);
      level.max[k] = std::max(level.max[k], v);
    }
  }
  levels_.push_back(std::move(level));
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& below = levels_.back();
    Level up;
    up.width = (below.width + kBlock - 1) / kBlock;
    up.height = (below.height + kBlock - 1) / kBlock;
    up.min.assign(size_t(up.width) * size_t(up.height), 1e30f);
    up.max.assign(up.min.size(), -1e30f);
    for (int j = 0; j < below.height; ++j) {
      for (int i = 0; i < below.width; ++i) {
        size_t from = size_t(j) * size_t(below.width) + size_t(i);
        size_t k = size_t(j / kBlock) * size_t(up.width) + size_t(i / kBlock);
        up.min[k] = std::min(up.min[k], below.min[from]);
        up.max[k] = std::max(up.max[k], below.max[from]);
      }
    }
    levels_.push_back(std::move(up));
  }
}

size_t GridData::memory_bytes() const {
  size_t bytes = codes_.size() * sizeof(int16_t);
  for (const Level& l : levels_) bytes += (l.min.size() + l.max.size()) * sizeof(float);
  return bytes;
}

HeightRange GridData::sample_range(int i0, int i1, int j0, int j1) const {
  const int w = spec_.width, h = spec_.height;
  j0 = std::clamp(j0, 0, h - 1);
  j1 = std::clamp(j1, 0, h - 1);
  if (i1 - i0 + 1 >= w) {
    i0 = 0;
    i1 = w - 1;
  } else {
    int shift = ((i0 % w) + w) % w - i0;
    i0 += shift;
    i1 += shift;
  }
  HeightRange r{1e300, -1e300};
  auto cover = [&](int a0, int a1) {
    // The finest level whose blocks cover the rectangle in at most about
    // 8 x 8 of them: level -1 is the samples themselves.
    int span = std::max(a1 - a0 + 1, j1 - j0 + 1), block = 1, level = -1;
    while (span > 8 * block && level + 1 < int(levels_.size())) {
      block *= kBlock;
      ++level;
    }
    if (level < 0) {
      for (int j = j0; j <= j1; ++j) {
        for (int i = a0; i <= a1; ++i) {
          double v = sample(i, j);
          r.min = std::min(r.min, v);
          r.max = std::max(r.max, v);
        }
      }
      return;
    }
    const Level& l = levels_[size_t(level)];
    for (int bj = j0 / block; bj <= j1 / block; ++bj) {
      for (int bi = a0 / block; bi <= a1 / block; ++bi) {
        size_t k = size_t(bj) * size_t(l.width) + size_t(bi);
        r.min = std::min(r.min, double(l.min[k]));
        r.max = std::max(r.max, double(l.max[k]));
      }
    }
  };
  if (i1 < w) {
    cover(i0, i1);
  } else {
    cover(i0, w - 1);
    cover(0, i1 - w);
  }
  return r;
}

GridHeight::GridHeight(std::shared_ptr<const GridData> data, double radius, double ellipsoid_ratio2,
                       std::optional<double> sea_level)
    : data_(std::move(data)),
      radius_(radius),
      ellipsoid_ratio2_(ellipsoid_ratio2),
      sea_level_(sea_level) {
  range_ = padded(data_->range_);
  if (sea_level_) {
    range_.min = std::max(range_.min, *sea_level_);
    range_.max = std::max(range_.max, *sea_level_);
  }
}

HeightRange GridHeight::padded(HeightRange samples) const {
  double pad = kOvershoot * data_->max_step_;
  return {std::max(samples.min - pad, data_->range_.min - pad),
          std::min(samples.max + pad, data_->range_.max + pad)};
}

void GridHeight::grid_coordinates(const glm::dvec3& d, double& u, double& v) const {
  const GridSpec& s = data_->spec_;
  double lon = std::atan2(d.y, d.x);
  double lat = s.geodetic_latitude
                   ? std::atan2(d.z * ellipsoid_ratio2_, std::sqrt(d.x * d.x + d.y * d.y))
                   : std::asin(std::clamp(d.z, -1.0, 1.0));
  double centre = s.registration == GridSpec::Registration::kPixel ? 0.5 : 0.0;
  double east = lon - glm::radians(s.west_longitude_deg);
  east -= 2.0 * kPi * std::floor(east / (2.0 * kPi));
  u = east * s.width / (2.0 * kPi) - centre;
  v = (0.5 * kPi - lat) * planet::rows_per_radian(s) - centre;
}

double GridHeight::seabed_height(const glm::dvec3& dir_body) const {
  const GridSpec& s = data_->spec_;
  double u, v;
  grid_coordinates(dir_body, u, v);
  double fu = std::floor(u), fv = std::floor(v);
  int i = int(fu), j = int(fv);
  double wu[4], wv[4];
  catmull_rom(u - fu, wu);
  catmull_rom(v - fv, wv);
  double h = 0;
  for (int b = 0; b < 4; ++b) {
    double row = 0;
    for (int a = 0; a < 4; ++a) row += wu[a] * data_->sample(i - 1 + a, j - 1 + b);
    h += wv[b] * row;
  }
  // Within the first row of a pole, into the pole's one value.
  double centre = s.registration == GridSpec::Registration::kPixel ? 0.5 : 0.0;
  double blend = pole_blend_rows(s);
  double from_north = v + centre, from_south = double(s.height) - 1.0 + 2.0 * centre - from_north;
  if (from_north < blend)
    h = data_->pole_[0] + smoothstep01(from_north / blend) * (h - data_->pole_[0]);
  if (from_south < blend)
    h = data_->pole_[1] + smoothstep01(from_south / blend) * (h - data_->pole_[1]);
  return h;
}

double GridHeight::height(const glm::dvec3& dir_body) const {
  double h = seabed_height(dir_body);
  return sea_level_ ? std::max(h, *sea_level_) : h;
}

double GridHeight::nearest_sample(const glm::dvec3& dir_body) const {
  double u, v;
  grid_coordinates(dir_body, u, v);
  return data_->sample(int(std::lround(u)), int(std::lround(v)));
}

double GridHeight::row_latitude(double v) const {
  const GridSpec& s = data_->spec_;
  double centre = s.registration == GridSpec::Registration::kPixel ? 0.5 : 0.0;
  return 0.5 * kPi - (v + centre) / planet::rows_per_radian(s);
}

double GridHeight::rows_per_radian() const { return planet::rows_per_radian(data_->spec_); }

HeightRange GridHeight::range_near(const glm::dvec3& dir_body, double radius) const {
  HeightRange r = seabed_range_near(dir_body, radius);
  if (sea_level_) {
    r.min = std::max(r.min, *sea_level_);
    r.max = std::max(r.max, *sea_level_);
  }
  return r;
}

HeightRange GridHeight::seabed_range_near(const glm::dvec3& dir_body, double radius) const {
  const GridSpec& s = data_->spec_;
  double u, v;
  grid_coordinates(dir_body, u, v);
  // The cap's angular radius, widened by 1 % for geodetic rows (whose
  // latitude stretches the direction's by at most (a/b)^2).
  double alpha = 1.01 * radius / radius_;
  double rows = alpha * planet::rows_per_radian(s);
  // The stencil reaches one sample before and two after floor(u), floor(v).
  int j0 = int(std::floor(v - rows)) - 1, j1 = int(std::ceil(v + rows)) + 2;
  int i0 = 0, i1 = s.width - 1;
  if (j0 < 0 || j1 > s.height - 1) {
    // Over a pole: every meridian, and the rows mirrored across it.
    j1 = std::max(j1, j0 < 0 ? -j0 : j1);
    j0 = std::min(j0, j1 > s.height - 1 ? 2 * (s.height - 1) - j1 : j0);
  } else {
    double lat_far = std::max(std::abs(planet::row_latitude(s, j0)), std::abs(planet::row_latitude(s, j1)));
    double cols = alpha / std::max(std::cos(lat_far), 1e-9) * s.width / (2.0 * kPi);
    if (2.0 * cols + 4.0 < s.width) {
      i0 = int(std::floor(u - cols)) - 1;
      i1 = int(std::ceil(u + cols)) + 2;
    }
  }
  return padded(data_->sample_range(i0, i1, j0, j1));
}

double GridHeight::interpolation_error(double spacing) const {
  // A surface whose slope never exceeds L leaves the chord between two of
  // its points `spacing` apart by at most L spacing / 2. Catmull-Rom's
  // slope stays within 1.5 times the steepest step between samples along
  // each axis, so within 1.5 sqrt(2) of it in any direction.
  double slope = 1.5 * glm::root_two<double>() * data_->max_slope_ / radius_;
  return std::min(range_.max - range_.min, 0.5 * slope * spacing);
}

}  // namespace planet
