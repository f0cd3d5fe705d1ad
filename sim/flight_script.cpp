#include "sim/flight_script.h"

#include "core/error.h"
#include "core/json_reader.h"

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

namespace {

glm::dquat body_from_enu_at(const Geodesy& geodesy, const Geodetic& g) {
  return glm::quat_cast(geodesy.body_from_enu(g));
}

// Looking from `eye` at `target` (body frame), the camera's up as close to
// the local vertical as the line of sight allows; straight down, the top of
// the image faces north.
glm::dquat look_at(const Geodesy& geodesy, const glm::dvec3& eye, const glm::dvec3& target) {
  glm::dvec3 forward = glm::normalize(target - eye);
  glm::dmat3 enu = geodesy.body_from_enu(geodesy.geodetic_from_body(eye));
  glm::dvec3 up_hint = enu[2];
  if (std::abs(glm::dot(forward, up_hint)) > 0.999999) up_hint = enu[1];
  glm::dvec3 right = glm::normalize(glm::cross(forward, up_hint));
  glm::dvec3 up = glm::cross(right, forward);
  return glm::normalize(glm::quat_cast(glm::dmat3(right, up, -forward)));
}

// A place's height, above the ellipsoid ("height_m") or above the ground
// under it ("height_above_ground_m"), as metres above the ellipsoid; the
// second also into `above_ground`. Below the ground is allowed a little (a
// cave, a trench) but not deep inside the body, where the geodetic mapping
// stops meaning anything.
double read_height(JsonObject& o, const Body& body, const Geodetic& place,
                   const GroundHeight& ground, double min_height, std::optional<double> fallback,
                   std::optional<double>* above_ground) {
  if (o.has("height_m") && o.has("height_above_ground_m")) {
    o.fail(
        "\"height_m\" (above the ellipsoid) and \"height_above_ground_m\" (above the "
        "ground) both given: give one");
  }
  if (!o.has("height_above_ground_m")) {
    if (!o.has("height_m") && !fallback) {
      o.fail(
          "give \"height_m\" (above the ellipsoid) or \"height_above_ground_m\" (above "
          "the ground)");
    }
    return o.number_or("height_m", fallback.value_or(0.0), min_height, 1e12);
  }
  double above = o.number("height_above_ground_m", min_height, 1e12);
  if (!ground) o.fail("height_above_ground_m", "this reader knows no ground to count from");
  double height = ground(body, place) + above;
  if (height < min_height) o.fail("height_above_ground_m", "is deep inside the body");
  if (above_ground) *above_ground = above;
  return height;
}

// A keyframe's position: geodetic, recorded in the body frame, or where the
// previous keyframe's orbit has carried the camera.
void read_position(JsonObject& k, const FlightScript& s, const Geodesy& geodesy,
                   const GroundHeight& ground, double min_height, bool orbit_before, Keyframe& f) {
  if (orbit_before) {
    for (const char* key :
         {"lat_deg", "lon_deg", "height_m", "height_above_ground_m", "position_body_m"}) {
      if (k.has(key)) k.fail(key, "the position comes from the orbit of the keyframe before");
    }
    const Keyframe& prev = s.keyframes.back();
    f.pos_body = body_state(s.body, prev.orbit->state_at(f.utc), f.utc).pos;
    f.place = geodesy.geodetic_from_body(f.pos_body);
  } else if (k.has("position_body_m")) {
    auto p = k.numbers("position_body_m", 3, -1e13, 1e13);
    f.pos_body = {p[0], p[1], p[2]};
    f.place = geodesy.geodetic_from_body(f.pos_body);
    if (f.place.height < min_height) k.fail("position_body_m", "is deep inside the body");
  } else {
    f.place.lat = glm::radians(k.number("lat_deg", -90.0, 90.0));
    f.place.lon = glm::radians(k.number("lon_deg", -180.0, 180.0));
    f.place.height =
        read_height(k, s.body, f.place, ground, min_height, std::nullopt, &f.height_above_ground);
    f.pos_body = geodesy.body_from_geodetic(f.place);
  }
}

// A keyframe's attitude: a recorded quaternion, a target, or heading,
// pitch and roll.
void read_attitude(JsonObject& k, const FlightScript& s, const Geodesy& geodesy,
                   const GroundHeight& ground, double min_height, Keyframe& f) {
  if (k.has("body_from_camera_wxyz")) {
    auto q = k.numbers("body_from_camera_wxyz", 4, -1.0, 1.0);
    f.body_from_camera = glm::dquat(q[0], q[1], q[2], q[3]);
    if (std::abs(glm::length(f.body_from_camera) - 1.0) > 1e-6) {
      k.fail("body_from_camera_wxyz", "is not a unit quaternion");
    }
  } else if (k.has("look_at")) {
    JsonObject t = k.object("look_at");
    Geodetic target{glm::radians(t.number("lat_deg", -90.0, 90.0)),
                    glm::radians(t.number("lon_deg", -180.0, 180.0)), 0.0};
    target.height = read_height(t, s.body, target, ground, min_height, 0.0, nullptr);
    t.finish();
    glm::dvec3 target_body = geodesy.body_from_geodetic(target);
    if (glm::length(target_body - f.pos_body) < 1e-3) k.fail("look_at", "is where the camera is");
    f.body_from_camera = look_at(geodesy, f.pos_body, target_body);
  } else {
    f.heading = glm::radians(k.number_or("heading_deg", 0.0, -360.0, 360.0));
    f.pitch = glm::radians(k.number_or("pitch_deg", 0.0, -90.0, 90.0));
    f.roll = glm::radians(k.number_or("roll_deg", 0.0, -180.0, 180.0));
    f.body_from_camera = glm::normalize(body_from_enu_at(geodesy, f.place) *
                                        enu_from_camera(f.heading, f.pitch, f.roll));
  }
}

// The "image" object: the frame's size and what it draws.
void read_image(JsonObject& root, FlightScript& s) {
  JsonObject image = root.object("image");
  s.width = image.integer("width", 1, 16384);
  s.height = image.integer("height", 1, 16384);
  s.antialiasing = image.integer_or("antialiasing", 4, 1, 16);
  if ((s.antialiasing & (s.antialiasing - 1)) != 0) {
    image.fail("antialiasing",
               fmt::format("{} samples a pixel: give 1 (none), 2, 4, 8 or 16", s.antialiasing));
  }
  s.terrain_shadows = image.boolean_or("terrain_shadows", true);
  s.stars = image.boolean_or("stars", true);
  s.glare = image.boolean_or("glare", false);
  s.clouds = image.boolean_or("clouds", false);
  image.finish();
}

// The frame rate, the exposure, the field of view and who chooses the sky.
void read_rendering(JsonObject& root, FlightScript& s) {
  s.frame_rate = root.number("frame_rate", 1e-3, 1000.0);
  if (s.frame_rate <= 0) root.fail("frame_rate", "must be positive");
  s.auto_exposure = root.has("exposure") && root.raw("exposure").is_string();
  if (s.auto_exposure) {
    if (root.string("exposure") != "auto") {
      root.fail("exposure", "is a positive number, or \"auto\" for each frame's own");
    }
  } else {
    s.exposure = root.number_or("exposure", 1.0, 0.0, 1e9);
    if (s.exposure <= 0) root.fail("exposure", "must be positive");
  }
  s.vertical_fov = glm::radians(root.number_or("vertical_fov_deg", 60.0, 1.0, 170.0));
  // The name is checked against the available techniques by the renderer
  // (sim knows no GL), with this file and field in the message.
  s.technique_named = root.has("technique");
  s.technique = root.string_or("technique", "hillaire");
  if (root.has("error_budget_pct")) {
    if (s.technique_named) {
      root.fail("error_budget_pct",
                "and \"technique\" both given: a named technique draws every frame, a budget "
                "lets the governor choose; give one");
    }
    double pct = root.number("error_budget_pct", -1e9, 1e9);
    if (!(pct > 0 && pct <= 1000)) {
      root.fail("error_budget_pct",
                fmt::format("{} is not a percentage above 0 and at most 1000", pct));
    }
    s.error_budget_percent = pct;
  }
  s.allow_below_ground = root.boolean_or("allow_below_ground", false);
}

// The sun: by the clock and the body's ephemeris, or fixed by hand.
void read_sun(JsonObject& root, FlightScript& s) {
  if (root.has("start_utc") == root.has("sun")) {
    root.fail(
        "give either \"start_utc\" (the sun from the body's ephemeris) or \"sun\" "
        "(elevation and azimuth), not both or neither");
  }
  if (root.has("start_utc")) {
    s.has_clock = true;
    s.start_utc = parse_utc(root.string("start_utc"), s.file.string() + ": start_utc");
    if (!s.body.ephemeris.available()) {
      root.fail("start_utc", s.body.name + " has no ephemeris; give the \"sun\" by hand instead");
    }
  } else {
    JsonObject sun = root.object("sun");
    s.sun_elevation = glm::radians(sun.number("elevation_deg", -90.0, 90.0));
    s.sun_azimuth = glm::radians(sun.number("azimuth_deg", -360.0, 360.0));
    sun.finish();
  }
}

// A keyframe's clock: set there, or running on from the previous keyframe's.
void read_clock(JsonObject& k, const FlightScript& s, size_t i, Keyframe& f) {
  if (k.has("utc") || k.has("clock_s")) {
    if (!s.has_clock) k.fail("the clock needs \"start_utc\" at the top of the script");
    if (k.has("utc") && k.has("clock_s")) k.fail("give \"utc\" or \"clock_s\", not both");
    f.utc = k.has("utc") ? parse_utc(k.string("utc"), k.file() + ": " + k.path() + ".utc")
                         : s.start_utc + k.number("clock_s", -1e12, 1e12);
  } else {
    f.utc = i == 0 ? s.start_utc : s.keyframes.back().utc + (f.time - s.keyframes.back().time);
  }
}

// A keyframe's orbit, which carries the camera to the next keyframe.
void read_orbit(JsonObject& k, const FlightScript& s, bool last, Keyframe& f) {
  if (last) k.fail("orbit", "needs a keyframe after it where the orbit ends");
  JsonObject o = k.object("orbit");
  double inclination = glm::radians(o.number("inclination_deg", 0.0, 180.0));
  bool northbound = o.string_or("direction", "north") != "south";
  if (o.has("direction") && o.string("direction") != "north" && o.string("direction") != "south") {
    o.fail("direction", "must be \"north\" or \"south\"");
  }
  o.finish();
  if (!s.has_clock) k.fail("orbit", "needs \"start_utc\": the body turns under an orbit");
  try {
    f.orbit = circular_orbit_over(s.body, f.place, inclination, northbound, f.utc);
  } catch (const InputError& e) {
    k.fail("orbit", e.what());
  }
}

}  // namespace

FlightScript load_flight_script(const std::filesystem::path& file, const GroundHeight& ground) {
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

  read_image(root, s);
  read_rendering(root, s);
  read_sun(root, s);

  Geodesy geodesy(s.body.shape);
  auto keys = root.objects("keyframes");
  if (keys.empty()) root.fail("keyframes", "must hold at least one keyframe");
  // The geodetic mapping is one-to-one above the ellipsoid's evolute, whose
  // shallowest point lies b^2 / a under the equator (a sphere's: its
  // centre); three quarters of that depth are allowed. Half the polar
  // radius, the bound before, put the deepest ground of Eros (5.4 km under
  // its 8.42 km sphere, 0.64 of it) out of reach; 5000 km under Earth's
  // surface stays refused.
  const double a = s.body.shape.equatorial_radius, b = s.body.shape.polar_radius();
  double min_height = -0.75 * b * b / a;
  bool orbit_before = false;
  for (size_t i = 0; i < keys.size(); ++i) {
    JsonObject& k = keys[i];
    Keyframe f;
    f.time = k.number("time", -1e9, 1e9);
    if (i > 0 && f.time <= s.keyframes.back().time) {
      k.fail("time", fmt::format("{:g} does not come after the previous keyframe's {:g}", f.time,
                                 s.keyframes.back().time));
    }
    read_clock(k, s, i, f);
    read_position(k, s, geodesy, ground, min_height, orbit_before, f);
    orbit_before = false;
    if (k.has("orbit")) {
      read_orbit(k, s, i + 1 == keys.size(), f);
      orbit_before = true;
    }
    read_attitude(k, s, geodesy, ground, min_height, f);
    if (s.auto_exposure && k.has("exposure")) {
      k.fail("exposure", "given where the script's exposure is \"auto\"");
    }
    f.exposure = k.number_or("exposure", s.exposure, 1e-9, 1e9);
    k.finish();
    s.keyframes.push_back(f);
  }
  root.finish();

  if (!s.has_clock) {
    const Geodetic& first = s.keyframes.front().place;
    glm::dvec3 sun_enu(std::cos(s.sun_elevation) * std::sin(s.sun_azimuth),
                       std::cos(s.sun_elevation) * std::cos(s.sun_azimuth),
                       std::sin(s.sun_elevation));
    s.sun_dir_body = glm::normalize(geodesy.body_from_enu(first) * sun_enu);
  } else {
    s.sun_dir_body = sun_dir_body(s.body.ephemeris, s.body.rotation, s.keyframes.front().utc);
  }
  return s;
}

FlightPath::FlightPath(const FlightScript& script) : script_(&script), geodesy_(script.body.shape) {
  std::vector<double> t, lat, lon, h, log_exposure;
  std::vector<glm::dquat> attitude;
  for (const Keyframe& k : script.keyframes) {
    t.push_back(k.time);
    lat.push_back(k.place.lat);
    lon.push_back(k.place.lon);
    h.push_back(k.place.height);
    attitude.push_back(k.body_from_camera);
    log_exposure.push_back(std::log(k.exposure));
  }
  lon = unwrapped(lon);
  lat_ = MonotoneCubic(t, lat);
  lon_ = MonotoneCubic(t, lon);
  height_ = MonotoneCubic(t, h);
  attitude_ = AttitudeCurve(t, attitude);
  log_exposure_ = MonotoneCubic(t, log_exposure);
  // Where an orbit begins or ends, the neighbouring cubic takes the
  // orbit's own rate of change: the path stays C1 across the junction.
  const auto& keys = script.keyframes;
  for (size_t i = 0; i + 1 < keys.size(); ++i) {
    if (!keys[i].orbit) continue;
    for (size_t end : {i, i + 1}) {
      const double dt = 1e-3;
      double time = keys[end].time;
      Geodetic a = place_on_orbit(*keys[i].orbit, utc_at(time - dt));
      Geodetic b = place_on_orbit(*keys[i].orbit, utc_at(time + dt));
      lat_.set_slope(end, (b.lat - a.lat) / (2 * dt));
      lon_.set_slope(end, std::remainder(b.lon - a.lon, 2.0 * glm::pi<double>()) / (2 * dt));
      height_.set_slope(end, (b.height - a.height) / (2 * dt));
    }
  }
}

Geodetic FlightPath::place_on_orbit(const KeplerOrbit& orbit, UtcSeconds utc) const {
  return geodesy_.geodetic_from_body(body_state(script_->body, orbit.state_at(utc), utc).pos);
}

size_t FlightPath::orbit_segment(double time) const {
  const auto& keys = script_->keyframes;
  for (size_t i = 0; i + 1 < keys.size(); ++i) {
    if (keys[i].orbit && time >= keys[i].time && time <= keys[i + 1].time) return i;
  }
  return std::string::npos;
}

double FlightPath::exposure_at(double time) const {
  for (const Keyframe& k : script_->keyframes) {
    if (k.time == time) return k.exposure;
  }
  return std::exp(log_exposure_(time));
}

UtcSeconds FlightPath::utc_at(double time) const {
  const auto& keys = script_->keyframes;
  if (time <= keys.front().time) return keys.front().utc + (time - keys.front().time);
  if (time >= keys.back().time) return keys.back().utc + (time - keys.back().time);
  size_t i = 0;
  while (keys[i + 1].time < time) ++i;
  if (time == keys[i + 1].time) return keys[i + 1].utc;
  double s = (time - keys[i].time) / (keys[i + 1].time - keys[i].time);
  return keys[i].utc + s * (keys[i + 1].utc - keys[i].utc);
}

glm::dvec3 FlightPath::sun_dir_at(double time) const {
  if (!script_->has_clock) return script_->sun_dir_body;
  return sun_dir_body(script_->body.ephemeris, script_->body.rotation, utc_at(time));
}

std::optional<glm::dvec3> FlightPath::companion_pos_at(double time) const {
  if (!script_->has_clock) return std::nullopt;
  return companion_pos_body(script_->body.ephemeris, script_->body.rotation, utc_at(time));
}

Geodetic FlightPath::place_at(double time) const {
  size_t orbit = orbit_segment(time);
  if (orbit != std::string::npos)
    return place_on_orbit(*script_->keyframes[orbit].orbit, utc_at(time));
  return {lat_(time), std::remainder(lon_(time), 2.0 * glm::pi<double>()), height_(time)};
}

Camera FlightPath::camera_at(double time) const {
  Camera c;
  c.vertical_fov = script_->vertical_fov;
  // At a keyframe, its exact pose: a recorded flight replays bit for bit.
  const Keyframe* exact = nullptr;
  for (const Keyframe& k : script_->keyframes) {
    if (k.time == time) exact = &k;
  }
  size_t orbit = orbit_segment(time);
  if (exact) {
    c.pos_body = exact->pos_body;
  } else if (orbit != std::string::npos) {
    UtcSeconds utc = utc_at(time);
    c.pos_body = body_state(script_->body, script_->keyframes[orbit].orbit->state_at(utc), utc).pos;
  } else {
    c.pos_body = geodesy_.body_from_geodetic(place_at(time));
  }
  c.body_from_camera = exact ? exact->body_from_camera : attitude_(time);
  return c;
}

}  // namespace planet
