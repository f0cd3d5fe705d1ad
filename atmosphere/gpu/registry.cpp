#include "atmosphere/gpu/registry.h"

#include "atmosphere/gpu/bruneton/bruneton_technique.h"
#include "atmosphere/gpu/hillaire/hillaire_technique.h"
#include "atmosphere/gpu/oneil/oneil_technique.h"
#include "atmosphere/gpu/raymarch/raymarch_technique.h"
#include "core/error.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace planet {

namespace {

// The terrain's shadow in the air: light shafts, shadowed haze.
const QualityParameter kTerrainShadowsParameter = {
    "terrain_shadows",
    "the terrain's shadow in the air (light shafts, shadowed haze)",
    0,
    1,
    1,
    true,
    {"off", "on"}};

std::vector<QualityParameter> hillaire_quality() {
  return {
      {"sky_view_steps", "march steps per texel of the sky-view LUT", 4, 128, 30, true, {}},
      {"per_pixel_steps",
       "march steps per pixel high up, in space and beyond the froxels",
       4,
       256,
       40,
       true,
       {}},
      {"aerial_substeps",
       "march steps per slice of the aerial-perspective froxels",
       1,
       16,
       2,
       true,
       {}},
      {"aerial_range_km", "distance the froxels cover near the ground, km", 1, 1000, 32, false, {}},
      {"path", "which path draws the frame", 0, 2, 0, true, {"by_altitude", "luts", "per_pixel"}},
      {"multiple",
       "the orders above the first; off: single scattering alone (for the lab's split by order)",
       0,
       1,
       1,
       true,
       {"off", "on"}},
      kTerrainShadowsParameter,
      {"space_view",
       "from outside the atmosphere, read the space-view LUT instead of marching each pixel: "
       "where the planet fills enough of the frame to pay for it (on), never, or always",
       0,
       2,
       1,
       true,
       {"off", "on", "always"}},
  };
}

std::unique_ptr<AtmosphereTechnique> make_hillaire(const TechniqueChoice& c,
                                                   HillaireTechnique::MultipleScattering ms) {
  HillaireTechnique::Settings s;
  s.multiple_scattering = ms;
  s.sky_view_steps = c.integer("sky_view_steps");
  s.per_pixel_steps = c.integer("per_pixel_steps");
  s.aerial_substeps = c.integer("aerial_substeps");
  s.aerial_range = c.value("aerial_range_km") * 1e3;
  s.path = HillaireTechnique::Path(c.integer("path"));
  s.multiple = c.integer("multiple") == 1;
  s.terrain_shadows = c.integer("terrain_shadows") == 1;
  s.space_view_lut = c.integer("space_view") > 0;
  if (c.integer("space_view") == 2) s.space_view_min_pixels = 0.0;
  return std::make_unique<HillaireTechnique>(s);
}

// The Moon's shadow in hillaire's marches and tables (both variants).
const char* const kHillaireMoonShadow =
    "yes: the share at each sample of its marches and tables, the multiply scattered light's as "
    "the sun's; the disk hidden";
// No technique draws a second light yet (the Moon's light by night).
const char* const kNoSecondLight = "no";

const std::vector<std::pair<std::string, std::string>> kHillaireQualityPoints = {
    {"cheap", "sky_view_steps=12,per_pixel_steps=12,aerial_substeps=1"},
    {"default", ""},
    {"fine", "sky_view_steps=64,per_pixel_steps=96,aerial_substeps=4"},
};

BrunetonTechnique::Settings bruneton_settings(const TechniqueChoice& c) {
  BrunetonTechnique::Settings s;
  s.r = c.integer("r_size");
  s.mu = c.integer("mu_size");
  s.mu_s = c.integer("mu_s_size");
  s.nu = c.integer("nu_size");
  s.transmittance_width = c.integer("transmittance_width");
  s.transmittance_height = c.integer("transmittance_height");
  s.irradiance_width = c.integer("irradiance_width");
  s.irradiance_height = c.integer("irradiance_height");
  s.orders = c.integer("orders");
  s.half = c.integer("floats") == 1;
  s.combined = c.integer("textures") == 1;
  s.integration_steps = c.integer("integration_steps");
  s.sphere_samples = c.integer("sphere_samples");
  s.transmittance_steps = c.integer("transmittance_steps");
  s.tail = c.integer("tail") == 1;
  return s;
}

std::unique_ptr<AtmosphereTechnique> make_bruneton(const TechniqueChoice& c) {
  return std::make_unique<BrunetonTechnique>(bruneton_settings(c));
}

std::unique_ptr<AtmosphereTechnique> make_oneil(const TechniqueChoice& c) {
  OneilTechnique::Settings s;
  s.samples = c.integer("samples");
  s.dome = c.integer("dome");
  s.cell = c.integer("cell");
  s.scale = OneilTechnique::Scale(c.integer("scale"));
  s.chapter_exposure = c.integer("exposure") == 1;
  return std::make_unique<OneilTechnique>(s);
}

TechniqueEntry raymarch_entry() {
  return {
      "raymarch",
      "Nishita et al. 1993",
      "single scattering by a nested ray march per pixel: the brute-force baseline",
      {{"view_steps", "march steps along each pixel's ray", 1, 512, 32, true, {}},
       {"light_steps", "march steps toward the sun at each of them", 1, 256, 16, true, {}},
       kTerrainShadowsParameter},
      {{"cheap", "view_steps=8,light_steps=4"},
       {"default", ""},
       {"fine", "view_steps=128,light_steps=64"}},
      "",
      "yes: the share at each sample of its march and on the ground; the disk hidden (exact for "
      "single scattering)",
      kNoSecondLight,
      [](const TechniqueChoice& c) {
        return std::make_unique<RaymarchTechnique>(RaymarchTechnique::Steps{
            c.integer("view_steps"), c.integer("light_steps"), c.integer("terrain_shadows") == 1});
      }};
}

TechniqueEntry hillaire_entry() {
  return {"hillaire",
          "ours, on Hillaire 2020's tables",
          "transmittance, multiple-scattering (six orders to spherical-harmonic degree 4 and a "
          "forward-gain LUT), sky-view and aerial-perspective LUTs; a per-pixel march high up",
          hillaire_quality(),
          kHillaireQualityPoints,
          "multiple=off",
          kHillaireMoonShadow,
          kNoSecondLight,
          [](const TechniqueChoice& c) {
            return make_hillaire(c, HillaireTechnique::MultipleScattering::kOrders);
          }};
}

TechniqueEntry bruneton_entry() {
  return {
      "bruneton",
      "Bruneton and Neyret 2008, as Bruneton reworked it in 2017",
      "transmittance, 4D single and multiple scattering and ground irradiance tables, the orders "
      "iterated on the GPU when the model changes and kept on disk",
      {{"r_size", "scattering table: altitudes", 4, 128, 32, true, {}},
       {"mu_size", "scattering table: view zenith cosines (even)", 4, 512, 256, true, {}},
       {"mu_s_size", "scattering table: sun zenith cosines", 4, 128, 64, true, {}},
       {"nu_size", "scattering table: view-sun cosines", 2, 64, 8, true, {}},
       {"transmittance_width", "transmittance table: view zenith cosines", 16, 2048, 256, true, {}},
       {"transmittance_height", "transmittance table: altitudes", 4, 1024, 64, true, {}},
       {"irradiance_width", "ground irradiance table: sun zenith cosines", 4, 1024, 64, true, {}},
       {"irradiance_height", "ground irradiance table: altitudes", 2, 256, 16, true, {}},
       {"orders", "orders of scattering iterated", 1, 50, 4, true, {}},
       {"floats", "the scattering tables' floats", 0, 1, 0, true, {"full", "half"}},
       {"textures",
        "single Mie in its own table, or its red in the scattering's alpha",
        0,
        1,
        0,
        true,
        {"separate", "combined"}},
       {"integration_steps",
        "steps along each ray of single and multiple scattering",
        4,
        500,
        50,
        true,
        {}},
       {"sphere_samples", "zenith angles of the gathers over the sphere", 4, 64, 16, true, {}},
       {"transmittance_steps",
        "quadrature steps of each transmittance texel",
        8,
        1000,
        100,
        true,
        {}},
       {"tail",
        "the orders past the last: left out (Bruneton's), or a geometric series",
        0,
        1,
        1,
        true,
        {"none", "geometric"}}},
      {{"cheap", "r_size=16,mu_size=64,mu_s_size=16,nu_size=4,orders=2,floats=half"},
       // Bruneton's own 2017 defaults.
       {"bruneton2017",
        "mu_size=128,mu_s_size=32,floats=half,textures=combined,tail=none,integration_steps=50"},
       {"default", ""},
       {"fine", "nu_size=16,orders=8,sphere_samples=24"}},
      // One order: no tail (it needs three), no sky light on the ground.
      "orders=1",
      "yes, one share per view ray: the mean along it, weighted as its single scattering, for "
      "every order; the ground's sun at its point; the disk hidden",
      kNoSecondLight,
      make_bruneton};
}

TechniqueEntry oneil_entry() {
  return {
      "oneil",
      "O'Neil 2005 (GPU Gems 2, ch. 16)",
      "single scattering per vertex of a sky dome and of a screen-space grid over the surfaces, "
      "the optical depths from a scale function fitted to the body's scale heights",
      // 8 samples: on earth_noon, 5 (the chapter's) left the sky 8-10 % (relative RMSE)
      // off single scattering by the fine ray march, 8 left 3-5 %, 10 2-4 %, of which
      // ozone, which O'Neil's model has not, is about 2 % in green.
      {{"samples", "samples along each vertex's ray", 2, 16, 8, true, {}},
       {"dome", "the sky dome's rings (twice as many segments around)", 4, 256, 48, true, {}},
       {"cell", "pixels between the vertices of the surfaces' grid", 1, 64, 8, true, {}},
       {"scale",
        "the scale function: fitted to the body, or the chapter's polynomial",
        0,
        1,
        0,
        true,
        {"fitted", "chapter"}},
       {"exposure",
        "radiance for the frame's tone map, or the chapter's 1 - exp(-exposure L) display values",
        0,
        1,
        0,
        true,
        {"tone_map", "chapter"}}},
      {{"cheap", "samples=4,dome=24,cell=16"},
       {"chapter", "samples=5,scale=chapter"},
       {"default", ""},
       {"fine", "samples=16,dome=96,cell=4"}},
      "",
      "yes: the share at each sample of its single scattering and on the ground; the disk hidden",
      kNoSecondLight,
      make_oneil};
}

TechniqueEntry hillaire2020_entry() {
  return {"hillaire2020",
          "Hillaire 2020",
          "the paper's LUTs, with its multiple scattering Psi = L2 / (1 - f_ms)",
          hillaire_quality(),
          kHillaireQualityPoints,
          "multiple=off",
          kHillaireMoonShadow,
          kNoSecondLight,
          [](const TechniqueChoice& c) {
            return make_hillaire(c, HillaireTechnique::MultipleScattering::kPaper);
          }};
}

std::vector<TechniqueEntry> make_registry() {
  return {raymarch_entry(), hillaire_entry(), bruneton_entry(), oneil_entry(),
          hillaire2020_entry()};
}

std::string format_value(const QualityParameter& p, double v) {
  if (!p.choices.empty()) return p.choices[size_t(v)];
  return fmt::format("{:g}", v);
}

// One key=value of a technique's text, checked against its parameter.
double parse_value(const TechniqueEntry& t, const QualityParameter& p, const std::string& text) {
  if (!p.choices.empty()) {
    auto it = std::find(p.choices.begin(), p.choices.end(), text);
    if (it == p.choices.end()) {
      throw InputError(fmt::format("{}: {}={} is not one of {}", t.name, p.key, text,
                                   fmt::join(p.choices, ", ")));
    }
    return double(it - p.choices.begin());
  }
  char* end = nullptr;
  double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) {
    throw InputError(fmt::format("{}: {}={} is not a number", t.name, p.key, text));
  }
  if (p.integer && v != std::floor(v)) {
    throw InputError(fmt::format("{}: {}={} is not a whole number", t.name, p.key, text));
  }
  if (v < p.min || v > p.max) {
    throw InputError(
        fmt::format("{}: {}={} is outside {:g} to {:g}", t.name, p.key, text, p.min, p.max));
  }
  return v;
}

}  // namespace

const std::vector<TechniqueEntry>& technique_registry() {
  static const std::vector<TechniqueEntry> registry = make_registry();
  return registry;
}

std::vector<std::string> technique_names() {
  std::vector<std::string> names;
  for (const auto& t : technique_registry()) names.push_back(t.name);
  return names;
}

const TechniqueEntry& technique_entry(const std::string& name) {
  for (const auto& t : technique_registry()) {
    if (t.name == name) return t;
  }
  throw InputError(fmt::format("unknown atmosphere technique '{}' (available: {})", name,
                               fmt::join(technique_names(), ", ")));
}

double TechniqueChoice::value(const std::string& key) const {
  for (const auto& [k, v] : values) {
    if (k == key) return v;
  }
  throw InputError(fmt::format("{}: no quality parameter '{}'", name, key));
}

std::string TechniqueChoice::text() const {
  const TechniqueEntry& t = technique_entry(name);
  std::string out;
  for (size_t i = 0; i < t.quality.size(); ++i) {
    const QualityParameter& p = t.quality[i];
    if (values[i].second == p.default_value) continue;
    out +=
        fmt::format("{}{}={}", out.empty() ? ":" : ",", p.key, format_value(p, values[i].second));
  }
  return name + out;
}

// The first of each pair: the names of parameters or quality points, for
// messages. (std::views::keys would do, but clang 14 cannot compile it
// against GCC 12's library, and the sanitizer builds use clang.)
template <class Pairs>
std::vector<std::string> keys_of(const Pairs& pairs) {
  std::vector<std::string> out;
  for (const auto& pair : pairs) out.push_back(pair.first);
  return out;
}

TechniqueChoice parse_technique(const std::string& text) {
  size_t colon = text.find(':');
  const TechniqueEntry& t = technique_entry(text.substr(0, colon));
  TechniqueChoice choice{t.name, {}};
  for (const auto& p : t.quality) choice.values.emplace_back(p.key, p.default_value);
  if (colon == std::string::npos) return choice;
  std::vector<std::string> point_names = keys_of(t.quality_points);
  // key=value items in turn; an item that names a quality point sets the
  // point's values, and the items after it may change them.
  auto apply = [&](const std::string& items, auto& self) -> void {
    size_t at = 0;
    while (true) {
      size_t comma = items.find(',', at);
      std::string item =
          items.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
      size_t eq = item.find('=');
      auto point = std::find_if(t.quality_points.begin(), t.quality_points.end(),
                                [&](const auto& q) { return q.first == item; });
      if (eq == std::string::npos && point != t.quality_points.end()) {
        if (!point->second.empty()) self(point->second, self);
      } else if (eq == std::string::npos || eq == 0) {
        throw InputError(fmt::format(
            "{}: '{}' is not key=value nor a quality point (its keys: {}; "
            "its points: {})",
            t.name, item, fmt::join(keys_of(choice.values), ", "), fmt::join(point_names, ", ")));
      } else {
        std::string key = item.substr(0, eq);
        auto it = std::find_if(t.quality.begin(), t.quality.end(),
                               [&](const QualityParameter& p) { return p.key == key; });
        if (it == t.quality.end()) {
          throw InputError(fmt::format("{} has no quality parameter '{}' (its parameters: {})",
                                       t.name, key, fmt::join(keys_of(choice.values), ", ")));
        }
        choice.values[size_t(it - t.quality.begin())].second =
            parse_value(t, *it, item.substr(eq + 1));
      }
      if (comma == std::string::npos) break;
      at = comma + 1;
    }
  };
  apply(text.substr(colon + 1), apply);
  return choice;
}

std::string single_scattering_text(const std::string& text) {
  const TechniqueEntry& t = technique_entry(text.substr(0, text.find(':')));
  if (t.single_scattering.empty()) return text;
  return text + (text.find(':') == std::string::npos ? ":" : ",") + t.single_scattering;
}

std::unique_ptr<AtmosphereTechnique> make_technique(const TechniqueChoice& choice) {
  return technique_entry(choice.name).make(choice);
}

std::unique_ptr<AtmosphereTechnique> make_technique(const std::string& text) {
  return make_technique(parse_technique(text));
}

uintmax_t disk_table_bytes(const TechniqueChoice& choice) {
  if (choice.name != "bruneton") return 0;
  return BrunetonTechnique::table_file_bytes(bruneton_settings(choice));
}

std::string describe_techniques() {
  std::string out =
      "Atmosphere techniques: pick one as NAME, NAME:KEY=VALUE,... or NAME:POINT[,KEY=VALUE...] "
      "(e.g. hillaire:per_pixel_steps=20, bruneton:cheap) on the command line or in a flight "
      "script's \"technique\".\n";
  for (const auto& t : technique_registry()) {
    out += fmt::format("\n{} ({}): {}\n", t.name, t.source, t.summary);
    for (const auto& p : t.quality) {
      std::string range = p.choices.empty() ? fmt::format("{}{:g} to {:g}",
                                                          p.integer ? "whole, " : "", p.min, p.max)
                                            : fmt::format("{}", fmt::join(p.choices, " | "));
      out += fmt::format("  {:<20} {:<31} default {:<12} {}\n", p.key, range,
                         format_value(p, p.default_value), p.description);
    }
    std::vector<std::string> points;
    for (const auto& [name, settings] : t.quality_points) points.push_back(name);
    out += fmt::format("  quality points for the lab: {}\n", fmt::join(points, ", "));
    out +=
        fmt::format("  single scattering alone (the lab's split by order): {}\n",
                    t.single_scattering.empty() ? "as it is" : t.name + ":" + t.single_scattering);
    out += fmt::format("  the Moon's shadow (the occluded sun): {}\n", t.moon_shadow);
    out += fmt::format("  a second light (the Moon's): {}\n", t.second_light);
  }
  return out;
}

}  // namespace planet
