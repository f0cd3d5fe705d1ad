#pragma once
// The one interface every GPU atmosphere technique implements (raymarch,
// hillaire, bruneton, oneil). A frame calls update() when the model
// changes, then render() to put sky, sun and aerial perspective over the
// opaque surfaces; the comparisons loop over techniques through it. The
// techniques and their quality parameters are listed in registry.h.
#include "atmosphere/model.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace planet {

struct PassTiming;
class GpuTimer;

// The terrain's shadow in the air for a frame (terrain/sun_shadow_field.h):
// an R32F texture of shadow heights (metres above the bottom sphere) over a
// gnomonic patch of atmosphere space about `up`, read by
// atmosphere/gpu/terrain_shadow.glsl. No texture: the frame has none (no
// relief, shadows turned off, a sun too high to leave any, or the camera
// high above the ground).
struct SkyTerrainShadow {
  GLuint texture = 0;
  glm::vec3 up{0, 0, 1}, east{1, 0, 0}, north{0, 1, 0};
  float bottom_radius = 0;
  float half_side = 0;  // metres from the patch's centre to its edge
  float strength = 0;   // 1: the whole shadow; fades to 0 as the camera rises
  float highest = 0;    // no shadow reaches above this altitude
  uint64_t version = 0;  // changes whenever the texture's contents do
  bool active() const { return texture != 0 && strength > 0.0f; }
};

// What a technique needs to know of a frame. "Atmosphere space" is the
// body frame scaled so that the body's ellipsoid becomes the atmosphere's
// bottom sphere (see atmosphere_space.h): the model stays spherical and
// still hugs an oblate planet.
struct SkyFrame {
  int width = 0, height = 0;
  glm::dvec3 camera_atmo{0.0};  // camera position in atmosphere space, metres
  // Maps (ndc.x, ndc.y, 1) to the unnormalised atmosphere-space direction of
  // the pixel, whose length is the atmosphere-space distance per unit of
  // view depth.
  glm::mat3 atmo_ray_from_ndc{1.0f};
  glm::vec3 sun_dir_atmo{0, 0, 1};
  // The Moon before the sun (an eclipse): its centre in atmosphere space
  // and its radius, metres; none while the radius is 0. A technique that
  // takes it multiplies the sun at each point by its visible share there
  // (occluded_sun.glsl).
  glm::vec3 moon_centre_atmo{0.0f};
  float moon_radius = 0.0f;
  float near = 0.1f;  // view depth at reversed-Z depth 1
  // No opaque surface drawn this frame lies nearer to the camera than this
  // (atmosphere-space metres; +inf when none was drawn); 0 when unknown. A
  // technique leaves out what serves only surfaces within a range beyond it.
  float nearest_surface = 0.0f;
  // The smallest of atmosphere space's scales of the body frame: a distance
  // d along a ray in atmosphere space is at most d / atmo_scale_min of view
  // depth.
  float atmo_scale_min = 1.0f;
  // False: leave nothing out by view (no pass skipped because no surface
  // needs it, no pixel because its ray misses the air): what pruning is
  // checked against.
  bool view_pruning = true;
  // The frame's tone-mapping exposure, for a technique that maps radiance
  // to display values itself (see writes_display_values).
  float exposure = 1.0f;
  SkyTerrainShadow terrain_shadow;
  // Inputs: reversed-Z depth (0 where nothing opaque was drawn) and the
  // radiance leaving opaque surfaces toward the camera, before the
  // atmosphere between them and the camera.
  GLuint depth_texture = 0;
  GLuint surface_texture = 0;
  // How far the surface under each pixel lies below the datum, metres (R,
  // 0 where it does not, or no texture): the air in front of it goes down
  // to it (sky_pixel.glsl's air_floor_radius), for the techniques that
  // march the air there.
  GLuint ground_below_texture = 0;
  static constexpr GLuint kGroundBelowUnit = 11;  // sky_pixel.glsl's u_ground_below
  // The lowest and the highest the ground can come anywhere on the body,
  // metres above the bottom sphere in atmosphere space (0, 0: a smooth
  // body): where a surface seen from space can stop a ray.
  glm::vec2 ground_heights{0.0f, 0.0f};
  // Output: an RGBA16F/32F framebuffer of the final HDR radiance, with an
  // 8-bit stencil cleared to 0 that the technique may use to restrict its
  // passes to the pixels they serve (a fragment shader's branches cost
  // their every side on a SIMD rasteriser such as llvmpipe; a pixel that
  // fails an early stencil test costs nothing). Leave the stencil test off.
  GLuint target_framebuffer = 0;
};

// A technique's update() cut into slices, for a window that keeps drawing
// another technique while this one builds its tables (fly's T): each
// step() does the next slice, as short as the work allows, between two
// frames. Every slice binds what it uses, so the frames drawn between
// slices change nothing of what the tables come to hold: done in slices or
// in one go, they are the same bytes.
class TableBuild {
 public:
  virtual ~TableBuild() = default;
  // The next slice; true once the tables are complete.
  virtual bool step() = 0;
  // How far it is, 0 to 1, and what it does now ("order 2 of 4").
  virtual double fraction() const = 0;
  virtual std::string what() const = 0;
};

class AtmosphereTechnique {
 public:
  virtual ~AtmosphereTechnique() = default;
  virtual std::string name() const = 0;
  // Takes new parameters; cheap when nothing changed.
  virtual void update(const AtmosphereModel& model) = 0;
  // update(model) in slices (TableBuild): the technique outlives the build
  // and draws nothing until it is done. The default is one slice, for the
  // techniques whose update takes a frame or less.
  virtual std::unique_ptr<TableBuild> update_in_slices(const AtmosphereModel& model);
  // The tables that depend on the model alone, for this frame; a frame
  // calls it before drawing its surfaces, which may light themselves with
  // ground_irradiance(). render() prepares them itself when not called.
  virtual void prepare(GpuTimer& timer) { (void)timer; }
  // Sky, sun disk and aerial perspective over the surfaces into the target.
  virtual void render(const SkyFrame& frame, GpuTimer& timer) = 0;
  // The sky's irradiance on horizontal ground per unit solar irradiance,
  // after prepare(): a one-row RGBA texture over the sun's zenith cosine
  // whose texel i of n holds mu_s = mu_s_from_sky_irradiance_u(i / (n - 1))
  // (lut_coordinates.glsl). 0 when the technique does not compute it;
  // the terrain then estimates its own.
  virtual GLuint ground_irradiance() const { return 0; }
  // The target holds display values in [0, 1] that the technique mapped
  // itself (O'Neil's 1 - exp(-exposure L)), not radiance: the frame's tone
  // map then passes them through unchanged.
  virtual bool writes_display_values() const { return false; }
  // The technique draws the terrain's shadow in the air from the frame's
  // SkyTerrainShadow: only then does a frame compute one.
  virtual bool takes_terrain_shadow() const { return false; }
};

// The default build: update() in one slice.
inline std::unique_ptr<TableBuild> AtmosphereTechnique::update_in_slices(
    const AtmosphereModel& model) {
  class OneSlice final : public TableBuild {
   public:
    OneSlice(AtmosphereTechnique& t, const AtmosphereModel& m) : technique_(t), model_(m) {}
    bool step() override {
      if (!done_) technique_.update(model_);
      done_ = true;
      return true;
    }
    double fraction() const override { return done_ ? 1.0 : 0.0; }
    std::string what() const override { return "its tables"; }

   private:
    AtmosphereTechnique& technique_;
    AtmosphereModel model_;
    bool done_ = false;
  };
  return std::make_unique<OneSlice>(*this, model);
}

}  // namespace planet
