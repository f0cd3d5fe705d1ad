// Hillaire 2020, sec. 5.3: the sky's luminance around the camera over the
// full azimuth, in the local frame whose z is up and whose x points to the
// sun's azimuth, at the camera's altitude. Below the horizon it holds the
// air in front of the ground and the lit ground itself.
//
// The sky is the same on both sides of the sun's vertical plane (the LUT
// holds no terrain), so that the azimuths phi and -phi, in columns x and
// W - 1 - x, hold one value: half the columns are marched (phi < 0) and
// each is written to its mirror image too. Not in an eclipse: the Moon's
// shadow has no such symmetry, and every column is marched.
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba16f, binding = 0) uniform writeonly image2D u_output;

uniform float u_camera_r;     // clamped into the atmosphere
uniform vec3 u_sun_dir_local;  // (sin, 0, cos) of the sun's zenith angle

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  bool mirrored = u_moon.w <= 0.0;
  int columns = mirrored ? kSkyViewLutWidth / 2 : kSkyViewLutWidth;
  if (texel.x >= columns || texel.y >= kSkyViewLutHeight) return;
  Atmosphere atmosphere = block_atmosphere();
  float u = (float(texel.x) + 0.5) / float(kSkyViewLutWidth);
  float v = (float(texel.y) + 0.5) / float(kSkyViewLutHeight);
  float mu, phi;
  sky_view_lut_view_from_uv(atmosphere, u_camera_r, u, v, mu, phi);
  float sin_theta = safe_sqrt(1.0 - mu * mu);
  vec3 dir = vec3(sin_theta * cos(phi), sin_theta * sin(phi), mu);
  vec3 origin = vec3(0.0, 0.0, u_camera_r);
  float t_end;
  bool hits_ground;
  ray_extent_inside(atmosphere, origin, dir, t_end, hits_ground);
  vec3 luminance, transmittance, f_ms;
  integrate_along(atmosphere, origin, dir, 0.0, t_end, u_sun_dir_local, SKY_VIEW_STEPS, kSourceSky,
                  kFieldInterpolated, hits_ground, luminance, transmittance, f_ms);
  imageStore(u_output, texel, vec4(luminance, 1.0));
  if (mirrored) {
    imageStore(u_output, ivec2(kSkyViewLutWidth - 1 - texel.x, texel.y), vec4(luminance, 1.0));
  }
}
