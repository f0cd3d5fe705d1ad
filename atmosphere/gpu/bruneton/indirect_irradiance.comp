// Bruneton 2017, "Ground irradiance": the irradiance on horizontal ground
// at (r, mu_s) of the light of order n - 1 (the sky's), over the upper
// hemisphere: SPHERE_SAMPLES / 2 zenith angles by 2 SPHERE_SAMPLES
// azimuths, as Bruneton's, of which half are traced (the light is even
// across the sun's vertical plane). Writes the order's irradiance and adds
// it to the sky's irradiance in all.
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"
#include "atmosphere/gpu/bruneton/order_radiance.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_delta_irradiance;
layout(rgba32f, binding = 1) uniform image2D u_irradiance;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= IRRADIANCE_WIDTH || texel.y >= IRRADIANCE_HEIGHT) return;
  Atmosphere atmosphere = block_atmosphere();
  float r, mu_s;
  bruneton_r_mu_s_from_irradiance_uv(
      atmosphere, (vec2(texel) + 0.5) / vec2(IRRADIANCE_WIDTH, IRRADIANCE_HEIGHT), r, mu_s);
  vec3 sun = vec3(safe_sqrt(1.0 - mu_s * mu_s), 0.0, mu_s);
  const int kThetas = SPHERE_SAMPLES, kPhis = 2 * SPHERE_SAMPLES;  // phi over [0, pi]
  const float dtheta = 0.5 * kPi / float(kThetas), dphi = kPi / float(kPhis);
  vec3 sum = vec3(0.0);
  for (int l = 0; l < kThetas; ++l) {
    float theta = (float(l) + 0.5) * dtheta;
    for (int m = 0; m < kPhis; ++m) {
      float phi = (float(m) + 0.5) * dphi;
      vec3 omega = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
      // Twice: the mirror image across the sun's plane.
      sum += order_radiance(atmosphere, r, omega.z, mu_s, dot(omega, sun), false) * omega.z *
             (2.0 * dtheta * dphi * sin(theta));
    }
  }
  imageStore(u_delta_irradiance, texel, vec4(sum, 1.0));
  imageStore(u_irradiance, texel, imageLoad(u_irradiance, texel) + vec4(sum, 0.0));
}
