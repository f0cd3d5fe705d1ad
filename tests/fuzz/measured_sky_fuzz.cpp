// One sample of a measured sky (data/measured/<day>/<capture>/...txt): the
// input's first line is the file's name, which carries the sample's index,
// azimuth and elevation; the rest is the file.
#include "fuzz_input.h"
#include "lab/measured_sky.h"

PLANET_FUZZ_TARGET(measured_sky) {
  std::string_view text = planet::fuzz::as_text(data, size);
  size_t newline = text.find('\n');
  if (newline == std::string_view::npos || newline == 0 || newline > 200) return 0;
  std::string name(text.substr(0, newline));
  if (name.find('/') != std::string::npos || name.find('\0') != std::string::npos ||
      name == "." || name == "..") {
    return 0;
  }
  std::filesystem::path file = planet::fuzz::write_input(text.substr(newline + 1), name);
  planet::fuzz::expect_only_input_errors([&] {
    int first_nm = 0, last_nm = 0;
    planet::MeasuredDirection d = planet::load_measured_direction(file, first_nm, last_nm);
    (void)planet::luminance_cd_m2(d.radiance, first_nm);
  });
  std::filesystem::remove(file);
  return 0;
}
