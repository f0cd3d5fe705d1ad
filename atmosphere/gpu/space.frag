// The pixels of a view from space whose rays miss the atmosphere's shell
// (outside its screen bound, atmosphere/screen_bound.h): black space and
// the sun's disk, unattenuated, as a technique's own sky pass draws them
// there to the bit (the same ray, the same disk), at a fraction of its cost.
// Compiled with NO_SUN_DISK it leaves the disk out, for the pixels outside
// the disk's own screen bound: its limb darkening, run by llvmpipe at every
// pixel, took two thirds of the pass from 40 000 km.
#include "atmosphere/shaders/atmosphere_block.glsl"
#include "atmosphere/gpu/sky_pixel.glsl"

in vec2 v_ndc;
layout(location = 0) out vec4 o_radiance;

layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_surface;
uniform vec3 u_camera;  // atmosphere space, metres
uniform mat3 u_ray_from_ndc;
uniform vec3 u_sun_dir;
uniform float u_near;
// The Moon's centre (atmosphere space) and radius, which hides the disk
// where it lies before it; none while the radius is 0 (SkyFrame).
uniform vec4 u_moon;

void main() {
  Atmosphere atmosphere = block_atmosphere();
  SkyPixel pixel = sky_pixel(atmosphere, u_depth, u_surface, v_ndc, u_ray_from_ndc, u_near, u_camera);
#ifdef NO_SUN_DISK
  vec3 radiance = pixel.surface;
#else
  vec3 radiance = pixel.surface;
  if (!moon_hides_sun(pixel.camera, pixel.dir, u_moon.xyz, u_moon.w)) {
    radiance += sun_disk_radiance(atmosphere, dot(pixel.dir, u_sun_dir));
  }
#endif
  o_radiance = vec4(min(radiance, vec3(6.0e4)), 1.0);
}
