#pragma once
// The stars behind the sky: one point each, drawn after the atmosphere
// into the frame's linear radiance where no surface is, dimmed by the
// air's transmittance along the ray, and seen as the eye sees them: a
// star's irradiance spread over the eye's resolution (a disc one arcminute
// across), whatever the pixel's size, so that the day sky hides it by its
// brightness through the exposure, as it hides it from the eye.
#include "gl/program.h"
#include "gl/texture.h"
#include "sim/camera.h"
#include "sim/star_catalogue.h"

#include <vector>

namespace planet {

// The radiance of a star of magnitude 0 seen by the eye, per unit of the
// sun's irradiance: 10^(-0.4 * 26.74) over the solid angle of a disc one
// arcminute across.
double star_radiance_per_sun(double magnitude);

struct StarView {
  glm::dmat3 body_from_icrf{1.0};
  // The sun's irradiance at 1 AU in the frame's units (per unit of the
  // solar irradiance on an airless body, W m^-2 nm^-1 under an atmosphere).
  glm::vec3 sun_at_1au{1.0f};
  // Under an atmosphere: its block is bound, and these place the camera in
  // atmosphere space (atmosphere_space.h).
  bool has_atmosphere = false;
  glm::dvec3 atmo_scale{1.0};
  // Multiplies the radiance: 1, or the exposure where the target holds
  // display values.
  float scale = 1.0f;
  // The frame's clouds (CloudPass::clouds_texture(), their transmittance
  // in alpha), which dim the stars behind them; 0: none drawn.
  GLuint clouds = 0;
};

class StarField {
 public:
  // Needs a current GL 4.5 context.
  explicit StarField(const std::vector<Star>& stars);
  // Adds the stars into `target` (bound as it is, blending on) where
  // `depth` (the frame's reversed-Z depth, 0 where no surface) is empty.
  void draw(GLuint target, int width, int height, GLuint depth, const Camera& camera,
            const StarView& view) const;

 private:
  Buffer vertices_;
  VertexArray vao_;
  Program program_;
  int count_ = 0;
};

}  // namespace planet
