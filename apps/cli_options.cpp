#include "apps/cli_options.h"

#include "core/data_paths.h"
#include "core/error.h"
#include "gl/schedule.h"
#include "sim/body.h"

namespace planet::apps {

std::vector<std::string> split_list(const std::vector<std::string>& words) {
  std::vector<std::string> items;
  for (const std::string& word : words) {
    bool first = true;
    for (size_t start = 0; start <= word.size(); first = false) {
      size_t end = word.find(',', start);
      if (end == std::string::npos) end = word.size();
      std::string piece = word.substr(start, end - start);
      start = end + 1;
      // A technique's next setting, not an item of its own; only within
      // one word, where the comma before it was written.
      bool setting = piece.find('=') != std::string::npos && piece.find(':') == std::string::npos;
      if (setting && !first && !items.empty()) {
        items.back() += "," + piece;
      } else if (!piece.empty()) {
        items.push_back(piece);
      }
    }
  }
  return items;
}

void add_schedule_option(CLI::App& command) {
  command
      .add_option_function<std::string>(
          "--schedule",
          [](const std::string& text) { set_schedule(parse_schedule(text, "--schedule")); },
          "How the atmosphere splits its passes: software (for llvmpipe and the like), plain "
          "(for a GPU) or auto (by the GL renderer)")
      ->type_name("software|plain|auto")
      ->default_str("auto");
}

CLI::Validator positive() {
  return CLI::Validator(
      [](std::string& input) {
        double value = 0;
        if (CLI::detail::lexical_cast(input, value) && value > 0) return std::string();
        return fmt::format("Value {} is not above 0", input);
      },
      "POSITIVE");
}

double checked_latitude_deg(double lat_deg, const std::string& option) {
  if (!(lat_deg >= -90.0 && lat_deg <= 90.0)) {
    throw InputError(fmt::format("{}: {} is not a latitude (-90 to 90 deg)", option, lat_deg));
  }
  return lat_deg;
}

double checked_longitude_deg(double lon_deg, const std::string& option) {
  if (!(lon_deg >= -180.0 && lon_deg <= 360.0)) {
    throw InputError(fmt::format(
        "{}: {} is not a longitude (-180 to 360 deg east: -180 to 180, or 0 to 360 as Mars' "
        "maps count)",
        option, lon_deg));
  }
  return lon_deg;
}

std::string longitude_text(double lon_deg, int decimals) {
  if (lon_deg < 0) return fmt::format("{:.{}f} deg W", -lon_deg, decimals);
  if (lon_deg <= 180) return fmt::format("{:.{}f} deg E", lon_deg, decimals);
  return fmt::format("{:.{}f} deg E ({:.{}f} deg W)", lon_deg, decimals, 360.0 - lon_deg, decimals);
}

std::string body_list_text() {
  std::vector<std::string> items;
  for (const std::string& name : shipped_body_names()) {
    // A body file that does not load is listed by its name alone: the
    // command that names it says what is wrong with it.
    std::string summary;
    try {
      summary = load_body(data_dir() / "planets" / (name + ".json")).summary;
    } catch (const std::exception&) {
    }
    items.push_back(summary.empty() ? name : fmt::format("{} [{}]", name, summary));
  }
  return fmt::format("{}", fmt::join(items, ", "));
}

std::string body_option_help(const std::string& what) {
  std::string bodies = body_list_text();
  if (bodies.empty()) return what;
  return fmt::format("{} ({})", what, bodies);
}

}  // namespace planet::apps
