#pragma once
// The kinds of option that several commands share, each read one way
// everywhere: lists, ranges, places on a body, and bodies by name.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace planet::apps {

// The items of a list option, given as any mix of words and commas
// (`--techniques raymarch,hillaire`, `--techniques raymarch hillaire`, the
// option repeated). A piece `key=value` with no `:` continues the item
// before it: a technique's own settings hold commas
// (`raymarch:view_steps=8,light_steps=4,hillaire` is two techniques). Empty
// pieces (a trailing comma) are dropped.
std::vector<std::string> split_list(const std::vector<std::string>& words);

// `option` from one word of a list: CLI::ValidationError naming it where
// the word is no T.
template <typename T>
T list_item(const std::string& option, const std::string& word) {
  T value{};
  if (!CLI::detail::lexical_cast(word, value)) {
    throw CLI::ValidationError(option,
                               fmt::format("'{}' is not a {}", word, CLI::detail::type_name<T>()));
  }
  return value;
}

// A list option: its items replace `values` (the defaults), read by
// split_list, so that every list takes commas and spaces alike.
template <typename T>
CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<T>& values,
                             const std::string& help) {
  CLI::Option* option = app.add_option(
      name,
      [&values, name](const CLI::results_t& words) {
        std::vector<std::string> items = split_list(words);
        if (items.empty()) throw CLI::ValidationError(name, "names nothing");
        values.clear();
        for (const std::string& item : items) values.push_back(list_item<T>(name, item));
        return true;
      },
      help);
  // One argument and up, and the words after it up to the next option.
  option->type_name(CLI::detail::type_name<T>())->expected(CLI::detail::expected_max_vector_size);
  return option;
}

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

// --schedule software|plain|auto: how the techniques the command builds
// split their passes (gl/schedule.h); auto, the default, goes by the GL
// renderer. A bad value: one line naming it, exit 2, before any work.
void add_schedule_option(CLI::App& command);

// The bodies of data/planets by name, each with its file's summary where it
// gives one: "asteroid [a tiny planet ...], earth, ...".
std::string body_list_text();

// "Body name or file (asteroid [...], earth, ...)": body_list_text().
std::string body_option_help(const std::string& what = "Body name or file");

}  // namespace planet::apps
