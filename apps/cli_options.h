#pragma once
// The kinds of option that several commands share, each read one way
// everywhere: ranges, places on a body, and bodies by name.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <string>

namespace planet::apps {

// CLI::Range with its bounds in the error as a person writes them
// (`-180 to 180`, not `-180.000000 to 180.000000`).
template <typename T>
CLI::Validator within(T min, T max) {
  CLI::Validator validator = CLI::Range(min, max);
  validator.operation([min, max](std::string& input) {
    T value{};
    if (CLI::detail::lexical_cast(input, value) && value >= min && value <= max) {
      return std::string();
    }
    return fmt::format("Value {} not in range {} to {}", input, min, max);
  });
  return validator;
}

// A number above 0 (CLI::PositiveNumber's error spells out the largest
// double, 309 digits).
CLI::Validator positive();

// A latitude in degrees, -90 to 90; InputError naming `option` otherwise.
double checked_latitude_deg(double lat_deg, const std::string& option);

// A longitude east in degrees, -180 to 360: maps of Mars count 0-360 east,
// and a place read off one is taken as it is. InputError naming `option`
// otherwise.
double checked_longitude_deg(double lon_deg, const std::string& option);

// The longitude named east or west as a map would: "2.35 deg E", "70 deg
// W" for -70, and past 180 both ways, "226.2 deg E (133.8 deg W)", so that
// it reads against maps of either kind; `decimals` places.
std::string longitude_text(double lon_deg, int decimals);

// "Body name or file (asteroid, earth, ...)", the names from data/planets.
std::string body_option_help(const std::string& what = "Body name or file");

}  // namespace planet::apps
