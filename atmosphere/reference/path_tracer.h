#pragma once
// The ground truth: a CPU volumetric path tracer in double precision over a
// spherical atmosphere (Medium) with a Lambertian ground.
//
// Per path, one channel (wavelength). Each segment is tracked through the
// tentative collisions of the channel's majorant (Woodcock et al. 1965):
// the sun's direct light is gathered along the whole segment by next-event
// estimation toward a point sampled uniformly on the sun disk, weighted by
// ratio-tracked transmittance (Novak et al. 2014) and zero inside the
// planet's shadow; the path itself continues by analog delta tracking
// (absorption ends it, scattering picks Rayleigh or Mie in proportion and a
// direction sampled exactly from that phase function: Rayleigh or
// Cornette-Shanks), through unlimited orders. The ground is Lambertian and
// reflects with its albedo as the Russian roulette survival probability, so
// every path keeps weight 1 and ends by escaping, absorption or roulette.
//
// Deterministic: each (scene seed, pixel, sample) has its own random stream
// (reference/sampling.h); pixels are independent and their samples are
// summed in order, so a render has the same bits at any thread count.
#include "atmosphere/reference/medium.h"
#include "atmosphere/reference/sampling.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
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
};

struct ReferenceSettings {
  int spp = 64;      // paths per pixel, spread evenly over the channels
  int threads = 0;   // 0: all cores
  uint64_t seed = 0; // the scene's seed
  TraceOptions trace;
  // Called now and then with the fraction of rows done.
  std::function<void(double)> progress;
};

struct ReferenceImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // linear sRGB radiance, rows top-down
  uint64_t paths = 0;
  double seconds = 0;
};

ReferenceImage render_reference(const Medium& medium, const ReferenceView& view,
                                const ReferenceSettings& settings);

// The radiance (per nm, in the units of the solar irradiance) arriving at
// `origin` from direction -dir, in one channel: one path of `rng`'s stream.
double trace_path(const Medium& medium, const MediumChannel& channel, glm::dvec3 origin,
                  glm::dvec3 dir, const glm::dvec3& sun_dir, const TraceOptions& options,
                  reference::Rng& rng);

struct RadianceEstimate {
  double mean = 0;
  double std_error = 0;
};
// `paths` paths of one channel in one direction, streams seeded from `seed`.
RadianceEstimate estimate_radiance(const Medium& medium, size_t channel,
                                   const glm::dvec3& origin, const glm::dvec3& dir,
                                   const glm::dvec3& sun_dir, const TraceOptions& options,
                                   int paths, uint64_t seed);

// Transmittance from `origin` along `dir` to the top of the atmosphere (0
// through the ground) by ratio tracking, one estimate.
double ratio_tracking_transmittance(const Medium& medium, const MediumChannel& channel,
                                    const glm::dvec3& origin, const glm::dvec3& dir,
                                    reference::Rng& rng);

}  // namespace planet
