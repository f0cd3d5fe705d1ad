#include "render/capture_overrides.h"

#include "atmosphere/gpu/registry.h"
#include "core/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace planet {

namespace {

// The script's own limits on an image side (sim/flight_script.cpp).
constexpr int kMaxSide = 16384;

std::string size_text(int width, int height) { return fmt::format("{}x{}", width, height); }

// What the command line said of the size, as the user typed it.
std::string size_option(const CaptureOverrides& o) {
  if (o.scale) return fmt::format("--scale {:g}", *o.scale);
  std::string text;
  if (o.width) text += fmt::format("--width {}", *o.width);
  if (o.height) text += fmt::format("{}--height {}", text.empty() ? "" : " ", *o.height);
  return text;
}

}  // namespace

void apply_capture_overrides(FlightScript& script, CaptureOverrides& overrides) {
  overrides.script_technique =
      script.technique_named ? script.technique
      : script.error_budget_percent
          ? fmt::format("governor, budget {:g} %", *script.error_budget_percent)
          : script.technique + " (the default)";
  overrides.script_width = script.width;
  overrides.script_height = script.height;
  if (overrides.technique) {
    try {
      parse_technique(*overrides.technique);
    } catch (const InputError& e) {
      throw InputError(fmt::format("--technique: {}", e.what()));
    }
    script.technique = *overrides.technique;
    script.technique_named = true;
  }
  for (auto [option, side] :
       {std::pair{"--width", overrides.width}, std::pair{"--height", overrides.height}}) {
    if (side && (*side < 1 || *side > kMaxSide)) {
      throw InputError(
          fmt::format("{}: {} is not an image side (1 to {} pixels)", option, *side, kMaxSide));
    }
  }
  if (overrides.scale) {
    if (overrides.width || overrides.height) {
      throw InputError(
          "--scale and --width/--height both given: give --scale (of the script's size) or the "
          "size");
    }
    const double scale = *overrides.scale;
    if (!(scale > 0.0 && scale <= 16.0)) {
      throw InputError(fmt::format("--scale: {:g} is not above 0 and at most 16", scale));
    }
    long width = std::lround(script.width * scale), height = std::lround(script.height * scale);
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
      throw InputError(fmt::format("--scale {:g}: makes {}'s {} image {}x{} pixels", scale,
                                   script.file.string(), size_text(script.width, script.height),
                                   width, height));
    }
    script.width = int(width);
    script.height = int(height);
  } else if (overrides.width || overrides.height) {
    // One side alone: the other keeps the script's aspect ratio.
    const double aspect = double(script.width) / script.height;
    long width =
        overrides.width ? *overrides.width : std::max(1L, std::lround(*overrides.height * aspect));
    long height =
        overrides.height ? *overrides.height : std::max(1L, std::lround(*overrides.width / aspect));
    if (width > kMaxSide || height > kMaxSide) {
      throw InputError(fmt::format("{}: makes the image {}x{} pixels, more than {} a side",
                                   size_option(overrides), width, height, kMaxSide));
    }
    script.width = int(width);
    script.height = int(height);
  }
}

nlohmann::json overrides_json(const CaptureOverrides& overrides) {
  nlohmann::json j = nlohmann::json::object();
  if (overrides.technique) {
    j["technique"] = {{"script", overrides.script_technique},
                      {"command_line", "--technique " + *overrides.technique}};
  }
  if (overrides.width || overrides.height || overrides.scale) {
    j["image_size"] = {{"script", size_text(overrides.script_width, overrides.script_height)},
                       {"command_line", size_option(overrides)}};
  }
  return j;
}

}  // namespace planet
