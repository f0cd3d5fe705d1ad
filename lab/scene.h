#pragma once
// The canonical scenes: fixed views that the ground truth and every GPU
// technique render, so that accuracy is always measured on the same pixels.
// A scene is a body (with an optional variant of its atmosphere), a camera
// as FrameRenderer takes it (pose in the body frame, vertical field of
// view, -z forward, +y up), a sun direction and an image size.
#include "atmosphere/model.h"
#include "atmosphere/reference/reference_render.h"
#include "sim/body.h"
#include "sim/camera.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace planet {

struct Scene {
  std::string name;
  std::string description;
  std::string body;  // a body name (data/planets/<body>.json) or file
  // Variants of the body's atmosphere: scattering multiplied (dense air)
  // and a replaced Mie asymmetry (strong forward scattering).
  double scattering_scale = 1.0;
  std::optional<double> mie_g;
  // The stability map's variants (lab/stability.h): absorption multiplied,
  // the body at another bottom radius (model.h, with_bottom_radius), the
  // scale heights stretched (with_scale_heights_scaled).
  double absorption_scale = 1.0;
  std::optional<double> bottom_radius;  // metres
  bool absolute_thickness = false;
  double scale_height_scale = 1.0;
  // The clarity views' grounds (lab/clarity.h): the ground of one albedo
  // at every wavelength in place of the model's, and a target's albedo
  // where the camera's rays meet the ground, the air around it lit over
  // the model's (TraceOptions::first_ground_albedo; the frame's palette).
  std::optional<double> ground_albedo;
  std::optional<double> target_albedo;
  Camera camera;
  glm::dvec3 sun_dir_body{0.0, 0.0, 1.0};
  int width = 128, height = 64;
  Projection projection = Projection::kPerspective;
  double exposure = 10.0;  // a tone-mapping exposure that shows the scene well
  // The orders of scattering its ground truth sums: 0 all of them, 1 single
  // scattering alone, N up to N events a path (reference --max-order).
  int max_order = 0;
  // The Moon before the sun (eclipse scenes): its centre in the body frame
  // and its radius, metres; none while the radius is 0.
  glm::dvec3 moon_pos_body{0.0};
  double moon_radius = 0;

  // Seeds the path tracer's random streams: a hash of the name.
  uint64_t seed() const;
};

// Where a scene's camera stands and looks, and where the sun is, in the
// local east-north-up frame of the point below the camera. Angles in
// degrees, the height above the body's ellipsoid in metres.
struct ScenePlacement {
  double lat_deg = 0, lon_deg = 0, height_m = 2.0;
  double heading_deg = 0, pitch_deg = 0, vertical_fov_deg = 90;
  double sun_elevation_deg = 0, sun_azimuth_deg = 0;  // azimuth clockwise from north
};
// The scene's camera and sun set from a placement on its body (scene_body:
// at its variant's radius).
Scene placed(Scene scene, const ScenePlacement& placement);

// Every canonical scene, at its default size (128x64).
std::vector<Scene> canonical_scenes();
// The eclipse scenes of 2024-04-08 at greatest eclipse (18:17 UTC), with
// the Sun and the Moon where the ephemeris puts them (sim/ephemeris.h):
// earth_eclipse_total, on the ground at the centre of totality looking
// north toward the horizon's glow; earth_eclipse_partial, due north of
// it where the visible share of the sun's flux (green) is 10 %; and
// earth_eclipse_400km, the umbra seen from 400 km north of it.
// Apart from the canonical scenes, whose table they leave as it stands.
std::vector<Scene> eclipse_scenes();
// The visible share (green) of the sun's flux at a point of a scene's
// body frame, with its Moon; 1 without one.
double scene_sun_share(const Scene& scene, const glm::dvec3& pos_body);

// A canonical or eclipse scene by name; InputError naming the known ones
// otherwise.
Scene find_scene(const std::string& name);
// The same, drawn at another size (the tests' 32x16).
Scene find_scene(const std::string& name, int width, int height);

// What names the scene's renders in the reference cache: "earth_noon-32x16",
// "earth_noon-order1-32x16" for its ground truth limited to one order.
std::string reference_stem(const Scene& scene);
// The --max-order value checked: 0 (all orders) to 1000; InputError otherwise.
int checked_max_order(int max_order, const std::string& where);

// The paths per pixel of a canonical scene's shipped 32x16 reference
// (data/reference), per channel where they differ: the first six were set
// for a noise below a tenth of the best technique's error, the newer six
// hold 4096. InputError for a name that is not a canonical scene.
PathBudget shipped_reference_paths(const std::string& scene_name);

// The lab's references, at the size `planet lab run` measures at: every
// canonical scene with an atmosphere, and its first order, ship at 64x32,
// with 8192 paths per pixel (earth_noon_dense50's full render 2048: its
// paths scatter hundreds of times). Their noise is comparable to the best
// techniques' errors, not a tenth of them: the lab takes it out of each
// error (debiased_error.h). A minute or a few each here.
constexpr int kLabWidth = 64, kLabHeight = 32;
PathBudget lab_reference_paths(const Scene& scene);

// What a scene renders: its body, and the body's atmosphere with the
// scene's variant applied. InputError for an airless body.
Body scene_body(const Scene& scene);
AtmosphereModel scene_atmosphere(const Scene& scene, const Body& body);

// What the scene fixes in a render of its ground truth: the budget, the
// seed of its random streams and the orders it sums (reference_render.h);
// the caller adds progress, checkpoints, cancel and shares.
ReferenceSettings reference_settings(const Scene& scene, const PathBudget& paths);

// The scene's camera in atmosphere space, ray for ray the one FrameRenderer
// builds (both are atmo_ray_from_ndc, atmosphere_space.h), for the path tracer.
ReferenceView reference_view(const Scene& scene, const Body& body, const AtmosphereModel& model);

}  // namespace planet
