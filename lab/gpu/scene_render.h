#pragma once
// A canonical scene drawn by a GPU technique through the frame, for the
// comparisons against its ground truth.
#include "core/image_io.h"
#include "lab/scene.h"

#include <string>

namespace planet {

// The scene through FrameRenderer with the named technique, at the scene's
// size: linear radiance, rows top-down like the reference. Needs a current
// GL context.
ImageRGB render_scene_with(const Scene& scene, const std::string& technique);
// The same, the technique confined to single scattering
// (single_scattering_text) and the surfaces lit by the sun alone: the
// frame's first order, for the ground truth's (Scene::max_order 1).
ImageRGB render_first_order_with(const Scene& scene, const std::string& technique);

}  // namespace planet
