#pragma once
// A scripted flight: a body, keyframes of geodetic position and attitude in
// time, a sun, and how to capture it. Sampling is a pure function of time,
// and capture samples at fixed steps of 1/frame_rate, so every run of a
// script yields the same cameras.
#include "sim/attitude_curve.h"
#include "sim/body.h"
#include "sim/camera.h"
#include "sim/geodesy.h"
#include "sim/interpolation.h"
#include "sim/kepler.h"
#include "sim/utc_time.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace planet {

struct Keyframe {
  double time = 0;  // seconds from the start of the flight
  Geodetic place;   // its height above the ellipsoid, however the file gave it
  // "height_above_ground_m" as the file gave it, where it gave that rather
  // than "height_m" (above the ellipsoid).
  std::optional<double> height_above_ground;
  double heading = 0, pitch = 0, roll = 0;  // radians, see enu_from_camera
  double exposure = 1;                      // the script's unless the keyframe gives its own
  // Resolved at load: the camera's attitude (from heading/pitch/roll, a
  // look-at target or a recorded quaternion) and its exact body position.
  glm::dquat body_from_camera{1, 0, 0, 0};
  glm::dvec3 pos_body{0.0};
  // The clock at this keyframe (scripts with "start_utc" only).
  UtcSeconds utc = 0;
  // From this keyframe to the next the camera rides this orbit.
  std::optional<KeplerOrbit> orbit;
};

struct FlightScript {
  std::filesystem::path file;
  std::string name;  // the file's stem, used to name captures
  Body body;
  std::vector<Keyframe> keyframes;
  double vertical_fov = glm::radians(60.0);
  // The sun's direction, fixed in the body frame for the whole flight, given
  // in the file as elevation and azimuth at the first keyframe's place.
  glm::dvec3 sun_dir_body{0, 0, 1};
  double sun_elevation = 0, sun_azimuth = 0;  // radians, as given
  int width = 0, height = 0;
  // "image": {"antialiasing": N}: samples a pixel for the surfaces' edges
  // (render/frame.h), 1 for none; 4 unless given.
  int antialiasing = 4;
  // "image": {"terrain_shadows": false}: the terrain casts no shadow from
  // the sun (terrain/horizon.h); on unless given.
  bool terrain_shadows = true;
  // "image": {"stars": false}: no stars behind the sky (render/star_field.h);
  // on unless given.
  bool stars = true;
  // "image": {"glare": true}: the eye's glare around the sun (render/frame.h's
  // FrameOptions::glare), as fly draws it; off unless given (or capture --glare).
  bool glare = false;
  // "image": {"clouds": true}: the body's cloud layer (its file's "clouds",
  // render/frame.h's FrameOptions::clouds); off unless given.
  bool clouds = false;
  double frame_rate = 0;
  double exposure = 1;  // multiplies radiance before tone mapping; the default for keyframes
  // "exposure": "auto": each frame's own, from its mean luminance
  // (render/frame.h); keyframes then give none.
  bool auto_exposure = false;
  std::string technique = "hillaire";
  bool technique_named = false;  // the file names it: it wins over any error budget
  // "error_budget_pct": the governor chooses each frame's technique within
  // this error (governor/governor.h).
  std::optional<double> error_budget_percent;
  // With "start_utc" the sun follows the body's ephemeris and the clock
  // (keyframes may set it with "utc" or "clock_s"); without it, the fixed
  // "sun" block holds.
  bool has_clock = false;
  UtcSeconds start_utc = 0;
  // "allow_below_ground": keyframes may lie under the terrain (a cave, a
  // view from inside); otherwise capture refuses them.
  bool allow_below_ground = false;

  double duration() const { return keyframes.back().time - keyframes.front().time; }
  // Frames at t = start + i / frame_rate for every such time in the flight.
  int frame_count() const;
  double frame_time(int frame) const;
};

// The ground's height above the ellipsoid under a place of a body: what a
// keyframe's "height_above_ground_m" counts from. sim knows no terrain; the
// terrain's ground is terrain_ground() (terrain/ground.h).
using GroundHeight = std::function<double(const Body& body, const Geodetic& place)>;

// A keyframe gives its height as "height_m" above the ellipsoid or as
// "height_above_ground_m" above the ground under it, which `ground` gives
// (without it such a keyframe is refused).
FlightScript load_flight_script(const std::filesystem::path& file, const GroundHeight& ground = {});

// Samples a flight at any time: positions and angles on monotone cubics
// through the keyframes.
class FlightPath {
 public:
  explicit FlightPath(const FlightScript& script);
  Camera camera_at(double time) const;
  Geodetic place_at(double time) const;
  // Interpolated in log space, so a 10x change takes as long up as down.
  double exposure_at(double time) const;
  // UTC at a time of the flight: linear between keyframes that set the
  // clock, one second per second elsewhere.
  UtcSeconds utc_at(double time) const;
  glm::dvec3 sun_dir_at(double time) const;
  // Where the Moon (over Earth) or the Earth (over the Moon) really is at
  // that time, body frame, metres: scripts with a clock only.
  std::optional<glm::dvec3> companion_pos_at(double time) const;

 private:
  size_t orbit_segment(double time) const;  // keyframe index, or npos
  Geodetic place_on_orbit(const KeplerOrbit& orbit, UtcSeconds utc) const;

  const FlightScript* script_;
  Geodesy geodesy_;
  MonotoneCubic lat_, lon_, height_, log_exposure_;
  AttitudeCurve attitude_;
};

}  // namespace planet
