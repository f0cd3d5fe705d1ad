#include "lab/gpu/scene_render.h"

#include "atmosphere/gpu/registry.h"
#include "render/frame.h"

namespace planet {

namespace {

ImageRGB render(const Scene& scene, const std::string& technique, bool sky_light) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  FrameRenderer renderer(scene.width, scene.height);
  FrameOptions options;
  options.surface_sky_light = sky_light;
  renderer.set_options(options);
  renderer.set_body(body, model, make_technique(technique));
  renderer.set_moon(scene.moon_pos_body, scene.moon_radius);
  renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);
  return image_from_gl(scene.width, scene.height, renderer.read_hdr());
}

}  // namespace

ImageRGB render_scene_with(const Scene& scene, const std::string& technique) {
  return render(scene, technique, true);
}

ImageRGB render_first_order_with(const Scene& scene, const std::string& technique) {
  return render(scene, single_scattering_text(technique), false);
}

}  // namespace planet
