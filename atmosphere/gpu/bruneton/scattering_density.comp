// Bruneton 2017, "Multiple scattering": the scattering density of order n,
// the light of order n - 1 (and the ground lit by the irradiance of order
// n - 2) scattered once more toward every direction, at every texel of the
// 4D table.
//
// Bruneton integrates, for every texel, over SPHERE_SAMPLES x
// 2 SPHERE_SAMPLES directions in the view's frame, each a lookup of the
// order before. But the light arriving at a point depends on (r, mu_s) and
// the direction alone, not on the view: here a work group takes one
// (r, mu_s), gathers that light once over the same grid of directions in
// the sun's frame (half of it: the light is even across the sun's vertical
// plane), and every (mu, nu) of its texels sums the phase functions against
// it. The lookups fall from 512 a texel to 256 a work group of 1024 texels.
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"
#include "atmosphere/gpu/bruneton/order_radiance.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D u_transmittance;
layout(binding = 3) uniform sampler2D u_delta_irradiance;  // order n - 2 on the ground
layout(rgba32f, binding = 0) uniform writeonly image3D u_density;

const int kThetas = SPHERE_SAMPLES, kPhis = SPHERE_SAMPLES;  // phi over [0, pi]
shared vec3 s_radiance[kThetas * kPhis];  // times the solid angle, and 2 for the mirror
shared vec3 s_direction[kThetas * kPhis];
// Rayleigh's phase is 3 / (16 pi) (1 + c^2): its sum against the light is
// 3 / (16 pi) (S + v^T M v) over the view v, with S the light's sum and M
// its second moments (a direction and its mirror across the sun's plane
// cancel the xy and yz terms). Summed once per work group, these take the
// Rayleigh phase out of the loop over directions of every texel.
shared vec3 s_moments[64][5];  // per invocation: S, xx, yy, zz, xz

void main() {
  Atmosphere atmosphere = block_atmosphere();
  int mu_s_index = int(gl_WorkGroupID.x);
  int r_index = u_first_layer + int(gl_WorkGroupID.y);
  float r, mu_unused, mu_s, nu_unused;
  bool ground_unused;
  bruneton_r_mu_mu_s_nu_from_texel(atmosphere, vec3(float(mu_s_index), 0.0, float(r_index)), r,
                                   mu_unused, mu_s, nu_unused, ground_unused);
  vec3 sun = vec3(safe_sqrt(1.0 - mu_s * mu_s), 0.0, mu_s);

  // The light arriving at (r, mu_s) from each direction of the grid.
  const float dtheta = kPi / float(kThetas), dphi = kPi / float(kPhis);
  for (int i = int(gl_LocalInvocationIndex); i < kThetas * kPhis; i += 64) {
    int l = i / kPhis, m = i - l * kPhis;
    float theta = (float(l) + 0.5) * dtheta, phi = (float(m) + 0.5) * dphi;
    vec3 omega = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
    bool ground = ray_intersects_ground(atmosphere, r, omega.z);
    vec3 radiance = order_radiance(atmosphere, r, omega.z, mu_s, dot(sun, omega), ground);
    if (ground) {
      // The ground lit by the order before, seen along omega.
      float d = distance_to_bottom_boundary(atmosphere, r, omega.z);
      vec3 normal = normalize(vec3(0.0, 0.0, r) + omega * d);
      vec3 irradiance = bruneton_irradiance(atmosphere, u_delta_irradiance, atmosphere.bottom_radius,
                                            dot(normal, sun));
      radiance += bruneton_transmittance(atmosphere, u_transmittance, r, omega.z, d, true) *
                  atmosphere.ground_albedo / kPi * irradiance;
    }
    s_radiance[i] = radiance * (2.0 * dtheta * dphi * sin(theta));
    s_direction[i] = omega;
  }
  barrier();
  vec3 m[5] = vec3[5](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
  for (int i = int(gl_LocalInvocationIndex); i < kThetas * kPhis; i += 64) {
    vec3 omega = s_direction[i], l = s_radiance[i];
    m[0] += l;
    m[1] += l * (omega.x * omega.x);
    m[2] += l * (omega.y * omega.y);
    m[3] += l * (omega.z * omega.z);
    m[4] += l * (omega.x * omega.z);
  }
  for (int k = 0; k < 5; ++k) s_moments[gl_LocalInvocationIndex][k] = m[k];
  barrier();
  vec3 sum_l = vec3(0.0), xx = vec3(0.0), yy = vec3(0.0), zz = vec3(0.0), xz = vec3(0.0);
  for (int j = 0; j < 64; ++j) {
    sum_l += s_moments[j][0];
    xx += s_moments[j][1];
    yy += s_moments[j][2];
    zz += s_moments[j][3];
    xz += s_moments[j][4];
  }

  float altitude = r - atmosphere.bottom_radius;
  vec3 sigma_r = atmosphere.rayleigh_scattering * profile_density(atmosphere.rayleigh_density, altitude);
  vec3 sigma_m = atmosphere.mie_scattering * profile_density(atmosphere.mie_density, altitude);
  // Mie's part is at most its phase function's peak times the light's sum,
  // Rayleigh's at least 3 / (16 pi) of it: where the first bound falls
  // under 2^-26 of the second in every channel, adding Mie's part cannot
  // change the density's float, and the loop over the directions is
  // skipped (on Earth above some 31 km, 14 of the 32 layers of r).
  float g = abs(atmosphere.mie_g);
  float mie_peak = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g) * 2.0 / ((1.0 - g) * (1.0 - g) * (1.0 - g));
  bool mie_counts = any(greaterThanEqual(sigma_m * mie_peak, sigma_r * (3.0 / (16.0 * kPi) / 67108864.0)));
  int mie_directions = mie_counts ? kThetas * kPhis : 0;
  for (int o = int(gl_LocalInvocationIndex); o < SCATTERING_MU * SCATTERING_NU; o += 64) {
    int mu_index = o / SCATTERING_NU, nu_index = o - mu_index * SCATTERING_NU;
    ivec3 texel = ivec3(nu_index * SCATTERING_MU_S + mu_s_index, mu_index, r_index);
    float r_t, mu, mu_s_t, nu;
    bool ground;
    bruneton_r_mu_mu_s_nu_from_texel(atmosphere, vec3(texel), r_t, mu, mu_s_t, nu, ground);
    // The view in the sun's frame: zenith cosine mu, at cosine nu to the sun.
    float sin_view = safe_sqrt(1.0 - mu * mu), sin_sun = safe_sqrt(1.0 - mu_s * mu_s);
    float cos_phi = sin_view * sin_sun > 1e-6 ? clamp((nu - mu * mu_s) / (sin_view * sin_sun), -1.0, 1.0)
                                              : 1.0;
    vec3 view = vec3(sin_view * cos_phi, sin_view * safe_sqrt(1.0 - cos_phi * cos_phi), mu);
    // Each direction and its mirror image carry half the light: the
    // moments' sum, with c0^2 + c1^2 = 2 (v.x o.x + v.z o.z)^2 + 2 (v.y o.y)^2.
    vec3 second = view.x * view.x * xx + view.y * view.y * yy + view.z * view.z * zz +
                  2.0 * view.x * view.z * xz;
    vec3 rayleigh = 3.0 / (16.0 * kPi) * (sum_l + second);
    vec3 mie = vec3(0.0);
    for (int i = 0; i < mie_directions; ++i) {
      vec3 omega = s_direction[i];
      // The direction and its mirror image across the sun's plane, which
      // carries the same light: half the solid angle each.
      float c0 = dot(view, omega);
      float c1 = dot(view, vec3(omega.x, -omega.y, omega.z));
      mie += (0.5 * s_radiance[i]) * (mie_phase(atmosphere, c0) + mie_phase(atmosphere, c1));
    }
    imageStore(u_density, texel, vec4(sigma_r * rayleigh + sigma_m * mie, 1.0));
  }
}
