// planet eclipse: the circumstances of the eclipse of a given UTC day, from
// the Sun and the Moon where ERFA puts them (sim/eclipse.h).
#include "apps/commands.h"
#include "core/error.h"
#include "sim/eclipse.h"
#include "sim/ephemeris.h"
#include "sim/utc_time.h"

#include <fmt/format.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

namespace planet::apps {

namespace {

// "18:17:16.4": the time of day of a UTC instant, to a tenth of a second.
std::string time_of_day_text(UtcSeconds t) {
  std::string iso = format_utc(std::round(t * 10.0) / 10.0);
  return iso.substr(11, 10);
}

std::string hemisphere_text(double rad, char positive, char negative) {
  double deg = glm::degrees(rad);
  return fmt::format("{:.3f} deg {}", std::abs(deg), deg < 0 ? negative : positive);
}

void print_solar(const SolarEclipse& e) {
  double td = e.greatest + tt_minus_utc(e.greatest);
  std::printf("eclipse           solar, %s\n", !e.central
                                                   ? "partial (the shadow's axis misses the Earth)"
                                               : e.total ? "total"
                                                         : "annular");
  std::printf("greatest eclipse  %s UTC  (%s TT; TT - UT1 = %.1f s)\n",
              time_of_day_text(e.greatest).c_str(), time_of_day_text(td).c_str(),
              delta_t(e.greatest));
  std::printf("gamma             %.4f\n", e.gamma);
  if (!e.central) return;
  std::printf("point             %s, %s\n", hemisphere_text(e.point.lat, 'N', 'S').c_str(),
              hemisphere_text(e.point.lon, 'E', 'W').c_str());
  std::printf("sun               altitude %.1f deg, azimuth %.1f deg\n",
              glm::degrees(e.sun_altitude), glm::degrees(e.sun_azimuth));
  std::printf("path width        %.1f km\n", e.path_width / 1000.0);
  int whole = int(e.central_duration);
  std::printf("central duration  %dm%04.1fs\n", whole / 60,
              e.central_duration - 60.0 * (whole / 60));
}

void print_lunar(const LunarEclipse& e) {
  const char* kind = e.u2 ? "total" : e.u1 ? "partial" : "penumbral";
  std::printf("eclipse           lunar, %s\n", kind);
  std::printf("greatest eclipse  %s UTC  (TT - UT1 = %.1f s)\n",
              time_of_day_text(e.greatest).c_str(), delta_t(e.greatest));
  std::printf("gamma             %.4f\n", e.gamma);
  std::printf("magnitude         umbral %.4f, penumbral %.4f\n", e.umbral_magnitude,
              e.penumbral_magnitude);
  auto contact = [](const char* name, const std::optional<UtcSeconds>& t) {
    if (t) std::printf("%-17s %s UTC\n", name, time_of_day_text(*t).c_str());
  };
  contact("P1", e.p1);
  contact("U1", e.u1);
  contact("U2", e.u2);
  contact("U3", e.u3);
  contact("U4", e.u4);
  contact("P4", e.p4);
}

void run(const std::string& date) {
  UtcSeconds day = parse_utc(date, "the date");
  if (std::fmod(day - 43200.0, 86400.0) != 0.0) {
    throw InputError(fmt::format("the date: '{}' must be a day (YYYY-MM-DD), not a time", date));
  }
  Eclipse e = find_eclipse(day);
  if (!e.solar && !e.lunar) {
    std::printf("no eclipse on %s (UTC)\n", date.c_str());
    return;
  }
  if (e.solar) print_solar(*e.solar);
  if (e.lunar) print_lunar(*e.lunar);
}

}  // namespace

void add_eclipse_command(CLI::App& app) {
  auto date = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "eclipse",
      "The circumstances of a UTC day's eclipse: greatest eclipse, central path, contacts");
  cmd->add_option("date", *date, "The UTC day, YYYY-MM-DD (e.g. 2024-04-08)")->required();
  cmd->callback([date] { run(*date); });
}

}  // namespace planet::apps
