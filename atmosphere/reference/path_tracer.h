#pragma once
// The ground truth: a CPU volumetric path tracer in double precision over a
// spherical atmosphere (Medium) with a Lambertian ground.
//
// Per path, one channel (wavelength). Every transmittance is exact to the
// depth table's interpolation (reference/columns.h): along a segment, the
// difference of two lookups; toward the sun, one (zero inside the planet's
// shadow). On each segment of a path (the camera ray, then one per
// scattering or reflection):
// - the sun's light scattered once along it is estimated at one point,
//   drawn from a table of that light along the segment, toward a point
//   sampled uniformly on the sun disk; the sunlit ground at its end and the
//   disk itself are added with the segment's transmittance;
// - the path goes on. A segment toward space is forced to collide, the
//   path's weight taking the chance that it does; one toward the ground
//   collides or reaches the ground by that chance. The collision point is
//   drawn in proportion to transmittance times extinction, and the weight
//   takes the single-scattering albedo; the ground takes its albedo. The
//   next direction comes from the phase function or from a lobe about the
//   sun (multiple importance sampling). Below a weight of 0.1 a path goes
//   on by Russian roulette, through unlimited orders.
// The first numbers of each path (two per segment and two per turn) come
// from Owen-scrambled Sobol pairs (reference/sampling.h), so the paths of
// a pixel are stratified over where they gather the sun, collide and turn.
//
// Deterministic: each (scene seed, pixel, replicate, channel) has its own
// scrambled sequence and each path its own random stream; pixels are
// independent and their samples are summed in order, so a render has the
// same bits at any thread count.
#include "atmosphere/reference/columns.h"
#include "atmosphere/reference/medium.h"
#include "atmosphere/reference/sampling.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace planet {

enum class Projection { kPerspective, kEquirectangular };

// What the camera sees, in atmosphere space (atmosphere/atmosphere_space.h).
struct ReferenceView {
  int width = 128, height = 64;
  glm::dvec3 camera_atmo{0.0};
  glm::dvec3 sun_dir_atmo{0.0, 0.0, 1.0};
  Projection projection = Projection::kPerspective;
  // Perspective: the ray through normalised device coordinates (x, y) is
  // ray_from_ndc * (x, y, 1), as FrameRenderer builds it, one ray through
  // each pixel's centre. Equirectangular: columns of `frame` are east,
  // north, up; columns run in azimuth from north through east, rows from
  // the zenith (top) to the nadir.
  glm::dmat3 ray_from_ndc{1.0};
  glm::dmat3 frame{1.0};
  // The Moon before the sun (TraceOptions): none while its radius is 0.
  glm::dvec3 moon_centre_atmo{0.0};
  double moon_radius = 0;

  // Unit ray direction through the centre of pixel (x, y), rows top-down.
  glm::dvec3 ray_dir(int x, int y) const;
};

struct TraceOptions {
  // Scattering events a path may have before it ends; 0 = unlimited.
  // 1 gives single scattering (the quadrature test).
  int max_order = 0;
  // Radiance arriving from every direction outside the atmosphere (a
  // furnace); the sun is then left out.
  double environment_radiance = 0;
  bool sun = true;
  // The Moon in front of the sun (an eclipse), in atmosphere space; none
  // while its radius is 0. Every sunlit term at a point (the air's and the
  // ground's) takes the visible share of the limb-darkened disk there
  // (occluded_sun.glsl) at the channel's wavelength, and the disk seen
  // directly is hidden where the Moon's sphere stands before it.
  glm::dvec3 moon_centre_atmo{0.0};
  double moon_radius = 0;
  // The ground's albedo where the camera's ray meets it (the first
  // segment's end), at every wavelength; the channel's everywhere else.
  // A target of that albedo too small to light the air around it: the
  // difference of two targets' radiances is then the view path's
  // transmittance times theirs (lab/clarity.h). Negative: none.
  double first_ground_albedo = -1.0;
};

// The radiance (per nm, in the units of the solar irradiance) arriving at
// `origin` from direction -dir, in the table's channel: one path, its
// numbers from `sampler`.
double trace_path(const DepthTable& table, glm::dvec3 origin, glm::dvec3 dir,
                  const glm::dvec3& sun_dir, const TraceOptions& options,
                  reference::PathSampler& sampler);

struct RadianceEstimate {
  double mean = 0;
  double std_error = 0;
};
// `paths` paths of one channel in one direction, streams seeded from `seed`.
RadianceEstimate estimate_radiance(const ColumnTable& columns, size_t channel,
                                   const glm::dvec3& origin, const glm::dvec3& dir,
                                   const glm::dvec3& sun_dir, const TraceOptions& options,
                                   int paths, uint64_t seed);

}  // namespace planet
