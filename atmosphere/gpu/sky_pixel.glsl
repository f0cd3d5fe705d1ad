// What every per-pixel sky pass starts from: the pixel's view ray in
// atmosphere space, the distance to the opaque surface under it (from the
// reversed-Z depth with an infinite far plane: view depth = near / depth)
// and the radiance that surface leaves, and the camera, lifted onto the
// bottom sphere when it is a hair below it (the ground mesh is an
// ellipsoid mapped onto the sphere, up to float rounding) or in a hollow
// below it; where nothing was drawn, the ray then passes over the lifted
// camera's horizon (lifted_horizon.glsl).
#include "atmosphere/gpu/lifted_horizon.glsl"

struct SkyPixel {
  float depth;      // reversed-Z; 0 where nothing opaque was drawn
  vec3 surface;     // radiance leaving the surface toward the camera; 0 without one
  vec3 dir;         // unit view direction (raised over the lifted horizon)
  float t_surface;  // distance to the surface along dir; 3e38 without one
  vec3 camera;      // lifted to at least 1 m above the bottom sphere
  float r_camera;   // the camera's distance from the centre before the lift
};

// The pixel `pixel` of the depth and surface textures, whose centre is at
// `ndc`: for a pass that works on other pixels than its fragment's (the
// clouds' march at a lower resolution).
SkyPixel sky_pixel_at(Atmosphere atmosphere, sampler2D depth_texture, sampler2D surface_texture,
                      ivec2 pixel, vec2 ndc, mat3 ray_from_ndc, float near, vec3 camera) {
  SkyPixel p;
  p.depth = texelFetch(depth_texture, pixel, 0).r;
  p.surface = p.depth > 0.0 ? texelFetch(surface_texture, pixel, 0).rgb : vec3(0.0);
  vec3 ray = ray_from_ndc * vec3(ndc, 1.0);
  float ray_scale = length(ray);
  p.dir = ray / ray_scale;
  p.t_surface = p.depth > 0.0 ? ray_scale * near / p.depth : 3.0e38;
  p.r_camera = length(camera);
  float r_min = atmosphere.bottom_radius + 1.0;
  p.camera = camera;
  if (p.r_camera < r_min) {
    p.camera = p.r_camera > 0.0 ? camera * (r_min / p.r_camera) : vec3(0, 0, r_min);
  }
  if (p.depth == 0.0) p.dir = over_the_lifted_horizon(atmosphere, p.camera, p.r_camera, p.dir);
  return p;
}

SkyPixel sky_pixel(Atmosphere atmosphere, sampler2D depth_texture, sampler2D surface_texture,
                   vec2 ndc, mat3 ray_from_ndc, float near, vec3 camera) {
  return sky_pixel_at(atmosphere, depth_texture, surface_texture, ivec2(gl_FragCoord.xy), ndc,
                      ray_from_ndc, near, camera);
}

// Where the air in front of the pixel's surface ends, as a radius: at the
// bottom sphere, which the facets of a coarse tile sag below (see
// hillaire_sky.frag), or lower where the ground under the pixel itself
// lies below the datum (a crater's floor, a canyon: terrain.frag), so that
// the air in a hollow is marched down to its floor, at the bottom's
// density (density.glsl). Heights count as metres of atmosphere space,
// whose scale differs from the body's by under 0.3 %.
layout(binding = 11) uniform sampler2D u_ground_below;
float air_floor_radius(Atmosphere atmosphere) {
  return atmosphere.bottom_radius + min(texelFetch(u_ground_below, ivec2(gl_FragCoord.xy), 0).r, 0.0);
}
