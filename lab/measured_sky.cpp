#include "lab/measured_sky.h"

#include "atmosphere/spectrum.h"
#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>

namespace planet {

namespace {

constexpr int kSamples = 81;
constexpr int kNeedFirstNm = 360, kNeedLastNm = 830;

}  // namespace

MeasuredDirection load_measured_direction(const std::filesystem::path& file, int& first_nm,
                                          int& last_nm) {
  static const std::regex kName(
      R"(^(\d{4}-\d{2}-\d{2})___(\d{2})\.(\d{2})\.(\d{2})_-_(\d+)____([0-9.]+)___([0-9.]+)\.asd\.rad\.txt$)");
  std::smatch m;
  std::string name = file.filename().string();
  if (!std::regex_match(name, m, kName)) {
    throw InputError(fmt::format(
        "{}: not a measured sample's name (DATE___HH.MM.SS_-_INDEX____AZIMUTH___ELEVATION"
        ".asd.rad.txt)",
        file.string()));
  }
  MeasuredDirection d;
  // The name's fields are digits (and dots), but may not be numbers ("1.2.3",
  // ".") or may not fit: read without exceptions, as the lines are.
  auto number = [](const std::string& text) {
    std::istringstream in(text);
    double v = std::numeric_limits<double>::quiet_NaN();
    if (!(in >> v) || in.peek() != std::char_traits<char>::eof()) return std::nan("");
    return v;
  };
  double index = number(m[5]);
  double azimuth_ccw = number(m[6]);
  d.elevation_deg = number(m[7]);
  if (!(index >= 0 && index < kSamples) || !(azimuth_ccw >= 0 && azimuth_ccw <= 360.0) ||
      !(d.elevation_deg >= 0 && d.elevation_deg <= 90.0)) {
    throw InputError(fmt::format("{}: index {} (0-80), azimuth {} (0-360) or elevation {} "
                                 "(0-90) out of range",
                                 file.string(), m[5].str(), m[6].str(), m[7].str()));
  }
  d.index = int(index);
  d.azimuth_deg = std::fmod(360.0 - azimuth_ccw, 360.0);

  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot be read", file.string()));
  std::string line;
  std::getline(in, line);  // the header: "Wavelength<TAB>name"
  if (line.rfind("Wavelength", 0) != 0) {
    throw InputError(fmt::format("{}:1: expected the header \"Wavelength ...\"", file.string()));
  }
  int line_number = 1, expected_nm = -1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::istringstream fields(line);
    int nm = 0;
    double value = 0;
    std::string rest;
    if (!(fields >> nm >> value) || (fields >> rest) || !std::isfinite(value)) {
      throw InputError(fmt::format("{}:{}: expected \"<wavelength nm> <radiance>\", got \"{}\"",
                                   file.string(), line_number, line));
    }
    if (nm < 0 || nm > 100000) {
      throw InputError(fmt::format("{}:{}: wavelength {} nm is not one of a spectrometer",
                                   file.string(), line_number, nm));
    }
    if (expected_nm >= 0 && nm != expected_nm) {
      throw InputError(fmt::format("{}:{}: wavelength {} nm where {} nm was expected (1 nm steps)",
                                   file.string(), line_number, nm, expected_nm));
    }
    if (expected_nm < 0) first_nm = nm;
    expected_nm = nm + 1;
    d.radiance.push_back(value);
  }
  if (d.radiance.empty()) throw InputError(fmt::format("{}: no spectrum", file.string()));
  last_nm = expected_nm - 1;
  if (first_nm > kNeedFirstNm || last_nm < kNeedLastNm) {
    throw InputError(fmt::format("{}: the spectrum covers {}-{} nm; {}-{} nm is needed",
                                 file.string(), first_nm, last_nm, kNeedFirstNm, kNeedLastNm));
  }
  return d;
}

namespace {

// The ring of samples at one elevation, in azimuth order.
std::map<double, std::vector<const MeasuredDirection*>> rings(const MeasuredCapture& c) {
  std::map<double, std::vector<const MeasuredDirection*>> out;
  for (const MeasuredDirection& d : c.directions) {
    if (d.elevation_deg < 89.0) out[d.elevation_deg].push_back(&d);
  }
  for (auto& [elevation, ring] : out) {
    std::sort(ring.begin(), ring.end(), [](const MeasuredDirection* a, const MeasuredDirection* b) {
      return a->azimuth_deg < b->azimuth_deg;
    });
  }
  return out;
}

}  // namespace

double MeasuredCapture::band_radiance(const MeasuredDirection& d, double lambda_nm) const {
  int lo = int(std::ceil(lambda_nm - 5.0)), hi = int(std::ceil(lambda_nm + 5.0)) - 1;
  lo = std::max(lo, first_nm);
  hi = std::min(hi, last_nm);
  double sum = 0;
  for (int nm = lo; nm <= hi; ++nm) sum += d.radiance[size_t(nm - first_nm)];
  return hi >= lo ? sum / double(hi - lo + 1) : 0.0;
}

MeasuredCapture load_measured_capture(const std::filesystem::path& dir, const MeasuredSite& site) {
  if (!std::filesystem::is_directory(dir)) {
    throw InputError(fmt::format("{}: not a folder of measured samples", dir.string()));
  }
  static const std::regex kFolder(R"(^(\d{4}-\d{2}-\d{2})___(\d{2})\.(\d{2})\.(\d{2})$)");
  std::smatch m;
  std::string folder = dir.filename().string();
  if (!std::regex_match(folder, m, kFolder)) {
    throw InputError(fmt::format("{}: a capture's folder is named DATE___HH.MM.SS", dir.string()));
  }
  MeasuredCapture c;
  c.dir = dir;
  c.date = m[1];
  int hours = std::stoi(m[2]), minutes = std::stoi(m[3]), seconds = std::stoi(m[4]);
  c.local = fmt::format("{:02}:{:02}", hours, minutes);
  double utc_minutes = hours * 60.0 + minutes - site.utc_offset_hours * 60.0;
  if (utc_minutes < 0.0 || utc_minutes >= 24.0 * 60.0) {
    throw InputError(fmt::format("{}: the capture's UTC falls on another day", dir.string()));
  }
  c.utc = fmt::format("{}T{:02}:{:02}:{:02}Z", c.date, int(utc_minutes) / 60, int(utc_minutes) % 60,
                      seconds);

  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::string name = entry.path().filename().string();
    if (name.size() > 12 && name.compare(name.size() - 12, 12, ".asd.rad.txt") == 0) {
      files.push_back(entry.path());
    }
  }
  c.directions.resize(kSamples);
  std::vector<bool> seen(kSamples, false);
  for (const auto& file : files) {
    int first = 0, last = 0;
    MeasuredDirection d = load_measured_direction(file, first, last);
    if (seen[size_t(d.index)]) {
      throw InputError(fmt::format("{}: sample {} appears twice", dir.string(), d.index));
    }
    if (c.first_nm == 0) {
      c.first_nm = first;
      c.last_nm = last;
    } else if (first != c.first_nm || last != c.last_nm) {
      throw InputError(fmt::format("{}: covers {}-{} nm, the capture's other samples {}-{} nm",
                                   file.string(), first, last, c.first_nm, c.last_nm));
    }
    seen[size_t(d.index)] = true;
    c.directions[size_t(d.index)] = std::move(d);
  }
  for (int i = 0; i < kSamples; ++i) {
    if (!seen[size_t(i)]) {
      throw InputError(fmt::format("{}: sample {} of 0-80 is missing ({} found)", dir.string(), i,
                                   files.size()));
    }
  }
  if (c.zenith().elevation_deg < 89.0) {
    throw InputError(fmt::format("{}: sample 80 is not the zenith", dir.string()));
  }
  // Sample 0 from its two neighbours on the lowest ring (see the header).
  std::vector<double>& north = c.directions[0].radiance;
  const std::vector<double>& east_of = c.directions[1].radiance;
  const std::vector<double>& west_of = c.directions[31].radiance;
  for (size_t i = 0; i < north.size(); ++i) north[i] = 0.5 * (east_of[i] + west_of[i]);
  c.repaired.push_back(0);
  return c;
}

std::vector<MeasuredCapture> load_measured_day(const std::filesystem::path& day_dir,
                                               const MeasuredSite& site) {
  if (!std::filesystem::is_directory(day_dir)) {
    throw InputError(fmt::format("{}: not a folder of measured captures", day_dir.string()));
  }
  std::vector<std::filesystem::path> folders;
  for (const auto& entry : std::filesystem::directory_iterator(day_dir)) {
    if (entry.is_directory()) folders.push_back(entry.path());
  }
  std::sort(folders.begin(), folders.end());
  std::vector<MeasuredCapture> out;
  for (const auto& folder : folders) out.push_back(load_measured_capture(folder, site));
  if (out.empty()) {
    throw InputError(fmt::format("{}: holds no capture folder (DATE___HH.MM.SS)", day_dir.string()));
  }
  return out;
}

double luminance_cd_m2(const std::vector<double>& radiance, int first_nm) {
  double sum = 0;
  for (size_t i = 0; i < radiance.size(); ++i) {
    int nm = first_nm + int(i);
    if (nm < 360 || nm > 830) continue;
    sum += cie1931_xyz(double(nm)).y * radiance[i];  // 1 nm steps
  }
  return 683.0 * sum;
}

double symmetry_azimuth_deg(const MeasuredCapture& capture, double around_deg) {
  // Each sample's radiance over 400-700 nm.
  auto power = [&](const MeasuredDirection& d) {
    double sum = 0;
    for (int nm = 400; nm <= 700; ++nm) sum += d.radiance[size_t(nm - capture.first_nm)];
    return sum;
  };
  auto all_rings = rings(capture);
  auto asymmetry = [&](double axis) {
    double error = 0;
    for (const auto& [elevation, ring] : all_rings) {
      size_t n = ring.size();
      double step = 360.0 / double(n);
      for (const MeasuredDirection* d : ring) {
        // The mirror image's azimuth, and the ring interpolated there.
        double mirror = std::fmod(2.0 * axis - d->azimuth_deg + 720.0, 360.0);
        double x = (mirror - ring[0]->azimuth_deg) / step;
        x = std::fmod(x + double(n), double(n));
        size_t i = size_t(x) % n;
        double f = x - std::floor(x);
        double value = (1.0 - f) * power(*ring[i]) + f * power(*ring[(i + 1) % n]);
        error += std::abs(power(*d) - value);
      }
    }
    return error;
  };
  double best = around_deg, best_error = asymmetry(around_deg);
  for (int k = -200; k <= 200; ++k) {
    double axis = around_deg + 0.1 * k;
    double e = asymmetry(axis);
    if (e < best_error) best_error = e, best = axis;
  }
  return std::fmod(best + 360.0, 360.0);
}

}  // namespace planet
