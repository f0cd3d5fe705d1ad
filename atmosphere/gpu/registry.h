#pragma once
// Every atmosphere technique in one table: its name, where it comes from,
// its quality parameters (ranges and defaults), its quality points from
// cheap to expensive, and the factory that builds it. The command line,
// flight scripts, the HUD and the comparisons all name a technique
// through it, as `name` or `name:key=value,...` (hillaire:per_pixel_steps=20).
#include "atmosphere/gpu/technique.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace planet {

struct QualityParameter {
  std::string key;
  std::string description;
  double min = 0, max = 0, default_value = 0;
  bool integer = true;
  // A choice among names instead of a number: the value is the index.
  std::vector<std::string> choices;
};

// A technique at a quality: its name and the value of every one of its
// parameters (the defaults where the text gave none), in the table's order.
struct TechniqueChoice {
  std::string name;
  std::vector<std::pair<std::string, double>> values;

  double value(const std::string& key) const;
  int integer(const std::string& key) const { return int(value(key)); }
  // "name", or "name:key=value,..." with the values that differ from the
  // defaults, in the table's order: what parse_technique reads back.
  std::string text() const;
};

struct TechniqueEntry {
  std::string name;
  std::string source;  // the paper or work it follows
  std::string summary;
  std::vector<QualityParameter> quality;
  // Quality points from cheap to expensive, each a name and the
  // `key=value,...` it sets (empty: the defaults), for the lab's sweeps.
  std::vector<std::pair<std::string, std::string>> quality_points;
  // The `key=value,...` that leaves the technique drawing single scattering
  // alone (empty: it draws nothing else), for the lab's split of its error
  // into the first order and the orders above it.
  std::string single_scattering;
  // How it takes the Moon's shadow in an eclipse (the sun's visible share,
  // occluded_sun.glsl), "no" where it does not; and the same for a second
  // light beside the sun (the Moon's): for `planet techniques`.
  std::string moon_shadow;
  std::string second_light;
  // Needs a current GL context.
  std::function<std::unique_ptr<AtmosphereTechnique>(const TechniqueChoice&)> make;
};

const std::vector<TechniqueEntry>& technique_registry();
std::vector<std::string> technique_names();
const TechniqueEntry& technique_entry(const std::string& name);

// Reads `name` or `name:key=value,...` against the table (no GL needed);
// InputError naming an unknown technique or key, a value that is not a
// number (or not one of the choices), or one out of range.
TechniqueChoice parse_technique(const std::string& text);

// `text` (name or name:key=value,...) with its entry's single_scattering
// settings after its own: the same technique drawing the first order alone.
std::string single_scattering_text(const std::string& text);

// Needs a current GL context.
std::unique_ptr<AtmosphereTechnique> make_technique(const TechniqueChoice& choice);
std::unique_ptr<AtmosphereTechnique> make_technique(const std::string& text);

// The bytes one model's tables of this choice take in the disk cache (0 for
// a technique that keeps nothing there); no GL needed.
uintmax_t disk_table_bytes(const TechniqueChoice& choice);

// The table as a person reads it: `planet techniques`.
std::string describe_techniques();

}  // namespace planet
