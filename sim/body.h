#pragma once
// A celestial body as the simulation sees it: its name, its shape and the
// parts of its file that other modules read (the atmosphere).
#include "core/json_reader.h"
#include "sim/body_rotation.h"
#include "sim/sun_ephemeris.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace planet {

// An oblate ellipsoid of revolution about the body's z axis.
struct Ellipsoid {
  double equatorial_radius = 0;  // a, metres
  double flattening = 0;         // f = (a - b) / a
  double polar_radius() const { return equatorial_radius * (1.0 - flattening); }
};

struct Body {
  std::string name;
  // What the body is, in a few words, where its name does not say it
  // ("asteroid" is a tiny planet, not a real one): the bodies' lists in
  // --help give it. Empty where the file gives none.
  std::string summary;
  std::filesystem::path file;
  Ellipsoid shape;
  // The "atmosphere" object of the body's file, parsed by the atmosphere
  // module; null for an airless body.
  nlohmann::json atmosphere;
  // Gravitational parameter GM, m^3 s^-2; 0 when the file gives none (no
  // orbits then).
  double gm = 0;
  // The spin; a body without "rotation" does not turn.
  BodyRotation rotation;
  bool has_rotation = false;
  // Where its sun is at a given time; none: scripts give the sun by hand.
  SunEphemeris ephemeris;
  // The "terrain" object, parsed by the terrain module; null for a smooth
  // ellipsoid.
  nlohmann::json terrain;
  // The "clouds" object, parsed by the clouds module; null for a body
  // without clouds.
  nlohmann::json clouds;

  bool has_atmosphere() const { return !atmosphere.is_null(); }
};

// Reads data/planets/<name>.json or any body file.
Body load_body(const std::filesystem::path& file);

// Finds a body file: an existing path is taken as it is, otherwise a bare
// name ("earth") is looked up in the shipped data/planets folder.
std::filesystem::path find_body_file(const std::string& name_or_path);

// The bare names find_body_file knows (data/planets/*.json), sorted; empty
// where that folder cannot be read. Every list of bodies a user is shown
// comes from here, so that a body file added there shows up in them.
std::vector<std::string> shipped_body_names();

}  // namespace planet
