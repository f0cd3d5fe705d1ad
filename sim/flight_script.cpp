#include "sim/flight_script.h"

#include "sim/error.h"
#include "sim/json_reader.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace planet {

namespace {

// Angles are unwrapped so that interpolation takes the short way round
// (a flight across the antimeridian does not circle the globe).
std::vector<double> unwrapped(std::vector<double> a) {
  for (size_t i = 1; i < a.size(); ++i) {
    double d = std::remainder(a[i] - a[i - 1], 2.0 * glm::pi<double>());
    a[i] = a[i - 1] + d;
  }
  return a;
}

}  // namespace

int FlightScript::frame_count() const {
  // The small epsilon keeps a frame that lands on the last keyframe up to
  // rounding, e.g. 40 s at 3 fps.
  return int(std::floor(duration() * frame_rate + 1e-9)) + 1;
}

double FlightScript::frame_time(int frame) const {
  return keyframes.front().time + double(frame) / frame_rate;
}

FlightScript load_flight_script(const std::filesystem::path& file) {
  JsonObject root = JsonObject::load(file);
  FlightScript s;
  s.file = file;
  s.name = file.stem().string();

  std::string body_name = root.string("body");
  try {
    s.body = load_body(find_body_file(body_name));
  } catch (const InputError& e) {
    root.fail("body", e.what());
  }

  JsonObject image = root.object("image");
  s.width = image.integer("width", 1, 16384);
  s.height = image.integer("height", 1, 16384);
  image.finish();

  s.frame_rate = root.number("frame_rate", 1e-3, 1000.0);
  if (s.frame_rate <= 0) root.fail("frame_rate", "must be positive");
  s.exposure = root.number_or("exposure", 1.0, 0.0, 1e9);
  if (s.exposure <= 0) root.fail("exposure", "must be positive");
  s.vertical_fov = glm::radians(root.number_or("vertical_fov_deg", 60.0, 1.0, 170.0));
  // The name is checked against the available techniques by the renderer
  // (sim knows no GL), with this file and field in the message.
  s.technique = root.string_or("technique", "hillaire");

  JsonObject sun = root.object("sun");
  s.sun_elevation = glm::radians(sun.number("elevation_deg", -90.0, 90.0));
  s.sun_azimuth = glm::radians(sun.number("azimuth_deg", -360.0, 360.0));
  sun.finish();

  auto keys = root.objects("keyframes");
  if (keys.empty()) root.fail("keyframes", "must hold at least one keyframe");
  double min_height = -s.body.shape.polar_radius() * 0.5;
  for (size_t i = 0; i < keys.size(); ++i) {
    JsonObject& k = keys[i];
    Keyframe f;
    f.time = k.number("time", -1e9, 1e9);
    if (i > 0 && f.time <= s.keyframes.back().time) {
      k.fail("time", fmt::format("{:g} does not come after the previous keyframe's {:g}",
                                 f.time, s.keyframes.back().time));
    }
    f.place.lat = glm::radians(k.number("lat_deg", -90.0, 90.0));
    f.place.lon = glm::radians(k.number("lon_deg", -180.0, 180.0));
    // Below the ground is allowed a little (a cave, a trench) but not deep
    // inside the body, where the geodetic mapping stops meaning anything.
    f.place.height = k.number("height_m", min_height, 1e12);
    f.heading = glm::radians(k.number_or("heading_deg", 0.0, -360.0, 360.0));
    f.pitch = glm::radians(k.number_or("pitch_deg", 0.0, -90.0, 90.0));
    f.roll = glm::radians(k.number_or("roll_deg", 0.0, -180.0, 180.0));
    f.exposure = k.number_or("exposure", s.exposure, 1e-9, 1e9);
    k.finish();
    s.keyframes.push_back(f);
  }
  root.finish();

  Geodesy geodesy(s.body.shape);
  const Geodetic& first = s.keyframes.front().place;
  glm::dvec3 sun_enu(std::cos(s.sun_elevation) * std::sin(s.sun_azimuth),
                     std::cos(s.sun_elevation) * std::cos(s.sun_azimuth),
                     std::sin(s.sun_elevation));
  s.sun_dir_body = glm::normalize(geodesy.body_from_enu(first) * sun_enu);
  return s;
}

FlightPath::FlightPath(const FlightScript& script)
    : script_(&script), geodesy_(script.body.shape) {
  std::vector<double> t, lat, lon, h, heading, pitch, roll, log_exposure;
  for (const Keyframe& k : script.keyframes) {
    t.push_back(k.time);
    lat.push_back(k.place.lat);
    lon.push_back(k.place.lon);
    h.push_back(k.place.height);
    heading.push_back(k.heading);
    pitch.push_back(k.pitch);
    roll.push_back(k.roll);
    log_exposure.push_back(std::log(k.exposure));
  }
  lat_ = MonotoneCubic(t, lat);
  lon_ = MonotoneCubic(t, unwrapped(lon));
  height_ = MonotoneCubic(t, h);
  heading_ = MonotoneCubic(t, unwrapped(heading));
  pitch_ = MonotoneCubic(t, pitch);
  roll_ = MonotoneCubic(t, unwrapped(roll));
  log_exposure_ = MonotoneCubic(t, log_exposure);
}

double FlightPath::exposure_at(double time) const { return std::exp(log_exposure_(time)); }

Geodetic FlightPath::place_at(double time) const {
  return {lat_(time), std::remainder(lon_(time), 2.0 * glm::pi<double>()), height_(time)};
}

Camera FlightPath::camera_at(double time) const {
  Geodetic g = place_at(time);
  Camera c;
  c.pos_body = geodesy_.body_from_geodetic(g);
  glm::dquat body_from_enu = glm::quat_cast(geodesy_.body_from_enu(g));
  c.body_from_camera =
      glm::normalize(body_from_enu * enu_from_camera(heading_(time), pitch_(time), roll_(time)));
  c.vertical_fov = script_->vertical_fov;
  return c;
}

}  // namespace planet
