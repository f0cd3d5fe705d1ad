#pragma once
// A measured sky: the clear-sky spectral radiance that Kider et al. 2014
// scanned at 81 directions of the sky over the roof of Rhodes Hall, Cornell
// (data/measured/kider-2013-05-27, its SOURCE.md), one folder a capture, in
// the data's own layout:
//   2013-05-27___09.30.00/2013-05-27___09.30.00_-_<i>____<azimuth>___<elevation>.asd.rad.txt
// each file a header line and then "<wavelength nm>\t<W m^-2 sr^-1 nm^-1>"
// every nanometre. The azimuth in the names runs counterclockwise from
// north (the brightest sample, circumsolar, lies at 360 - the sun's
// clockwise azimuth in every capture), the elevation is in degrees, and the
// folder's time is local (EDT, UTC - 4 h).
#include <filesystem>
#include <string>
#include <vector>

namespace planet {

// Where and when the measurements were taken.
struct MeasuredSite {
  double lat_deg = 42.443449, lon_deg = -76.481962;  // Kider et al.'s README
  double utc_offset_hours = -4.0;                     // EDT
};

struct MeasuredDirection {
  int index = 0;             // 0-80, the scan's order
  double azimuth_deg = 0;    // clockwise from north
  double elevation_deg = 0;  // above the horizon
  // Spectral radiance, W m^-2 sr^-1 nm^-1, every nm from the capture's first_nm.
  std::vector<double> radiance;
};

struct MeasuredCapture {
  std::filesystem::path dir;
  std::string date;   // "2013-05-27"
  std::string local;  // "09:30", the folder's local time
  std::string utc;    // "2013-05-27T13:30:00Z"
  int first_nm = 0, last_nm = 0;
  // By index. Sample 0 (north, 12 degrees up) is low in six of the eight
  // shipped captures (60-75 % of its two neighbours on its ring, which agree
  // within 12 %): the loader replaces it by their mean, as Bruneton's 2016
  // evaluation did, and says so in `repaired`.
  std::vector<MeasuredDirection> directions;
  std::vector<int> repaired;

  // The radiance of direction `d` averaged over [lambda - 5, lambda + 5) nm:
  // the 10 nm bin of the models' spectral samples.
  double band_radiance(const MeasuredDirection& d, double lambda_nm) const;
  // The direction at the zenith (index 80).
  const MeasuredDirection& zenith() const { return directions.back(); }
};

// One sample's file: its name gives the index, azimuth and elevation, its
// lines the spectrum; `first_nm` and `last_nm` the wavelengths it covers.
// InputError naming the file (and line) as below.
MeasuredDirection load_measured_direction(const std::filesystem::path& file, int& first_nm,
                                          int& last_nm);

// One capture's folder. InputError naming the folder or the file (and its
// line) for a missing or extra sample, a malformed name or line, a gap in
// the wavelengths, or a spectrum that does not cover 360-830 nm.
MeasuredCapture load_measured_capture(const std::filesystem::path& dir,
                                      const MeasuredSite& site = {});

// Every capture folder under `day_dir` (named DATE___HH.MM.SS), in time
// order; InputError if there is none.
std::vector<MeasuredCapture> load_measured_day(const std::filesystem::path& day_dir,
                                               const MeasuredSite& site = {});

// Luminance, cd/m^2: 683 lm/W times the integral of the CIE 1931 y-bar
// function times the spectral radiance (sampled every 1 nm from first_nm),
// over 360-830 nm.
double luminance_cd_m2(const std::vector<double>& radiance, int first_nm);

// The sun's azimuth (degrees clockwise from north) as the sky gives it: the
// axis about which the measured radiance (400-700 nm) is most nearly
// mirror-symmetric, searched every 0.1 degree within 20 degrees of
// `around_deg`. Each of the four rings is mirrored through linear
// interpolation along itself.
double symmetry_azimuth_deg(const MeasuredCapture& capture, double around_deg);

}  // namespace planet
