#include "lab/scene_render.h"

#include "atmosphere/gpu/registry.h"
#include "render/frame.h"

namespace planet {

ImageRGB render_scene_with(const Scene& scene, const std::string& technique) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  FrameRenderer renderer(scene.width, scene.height);
  renderer.set_body(body, model, make_technique(technique));
  renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);
  return image_from_gl(scene.width, scene.height, renderer.read_hdr());
}

}  // namespace planet
