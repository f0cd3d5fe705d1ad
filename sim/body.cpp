#include "sim/body.h"

#include "core/data_paths.h"
#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <system_error>

namespace planet {

Body load_body(const std::filesystem::path& file) {
  JsonObject root = JsonObject::load(file);
  Body body;
  body.file = file;
  body.name = root.string("name");
  if (body.name.empty()) root.fail("name", "must not be empty");
  body.summary = root.string_or("summary", "");

  JsonObject shape = root.object("shape");
  std::string type = shape.string("type");
  if (type != "ellipsoid")
    shape.fail("type", fmt::format("'{}' is not a known shape (ellipsoid)", type));
  body.shape.equatorial_radius = shape.number("equatorial_radius_m", 1.0, 1e9);
  // Flattening below 0 would be a prolate body, which GeographicLib allows
  // but nothing here expects; 0.5 is already a very squashed body.
  body.shape.flattening = shape.number_or("flattening", 0.0, 0.0, 0.5);
  shape.finish();

  if (root.has("atmosphere")) body.atmosphere = root.raw("atmosphere");
  body.gm = root.number_or("gm_m3_s2", 0.0, 0.0, 1e22);
  if (root.has("rotation")) {
    body.rotation = parse_rotation(root.object("rotation"));
    body.has_rotation = true;
  }
  if (root.has("ephemeris")) {
    body.ephemeris = parse_ephemeris(root.object("ephemeris"));
    // Only Mars24 gives the sun in the body frame by itself.
    if (!body.has_rotation && body.ephemeris.model != SunEphemeris::Model::kMars24) {
      root.fail("ephemeris", "needs the body's \"rotation\" to turn the sun into the body frame");
    }
  }
  if (root.has("terrain")) body.terrain = root.raw("terrain");
  if (root.has("clouds")) body.clouds = root.raw("clouds");
  root.string_or("source", "");  // where the values come from, for the reader
  root.finish();
  return body;
}

std::filesystem::path find_body_file(const std::string& name_or_path) {
  // A folder of the body's name where the command runs (`mars/` for a
  // capture's output) is not the body file: the shipped body is.
  std::filesystem::path p(name_or_path);
  std::error_code ec;
  bool folder = std::filesystem::is_directory(p, ec);
  if (!folder && std::filesystem::exists(p)) return p;
  std::filesystem::path shipped = data_dir() / "planets" / (name_or_path + ".json");
  if (std::filesystem::exists(shipped)) return shipped;
  if (folder) {
    throw InputError(fmt::format(
        "{}: a folder, not a body file, and no body of that name in {} ({})", name_or_path,
        (data_dir() / "planets").string(), fmt::join(shipped_body_names(), ", ")));
  }
  throw InputError(fmt::format("{}: no such body file, and no body of that name in {} ({})",
                               name_or_path, (data_dir() / "planets").string(),
                               fmt::join(shipped_body_names(), ", ")));
}

std::vector<std::string> shipped_body_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(data_dir() / "planets", ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->path().extension() == ".json") names.push_back(it->path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace planet
