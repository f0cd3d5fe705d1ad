// Ground and aerial perspective (O'Neil's "ground from atmosphere" and
// "ground from space") on a screen-space grid, one vertex every u_cell
// pixels: the frame gives the technique depth, not the terrain's vertices.
// Each vertex reads the depth under it and sums the single scattering and
// the transmittance along its ray to that surface, or to the bottom sphere
// where no surface was drawn; a vertex over open sky marks itself, so that
// the pixels near it evaluate their own rays (oneil_ground.frag).
#include "atmosphere/gpu/oneil/oneil_common.glsl"

uniform int u_cell;
uniform int u_columns;

out vec3 v_rayleigh;
out vec3 v_mie;
out vec3 v_transmittance;
// 1 / the distance to the surface or the ground along the unit ray: over a
// plane it is linear across the screen, as the grid interpolates it.
out float v_inverse_distance;
out float v_sky;       // 1 for a vertex over open sky
// The light leaving the bottom sphere where the vertex's ray meets it, and
// 1 where it does (else 0 for both): for the pixels of the sphere where no
// surface was drawn, interpolated where all three of a triangle's vertices
// meet the sphere.
out vec3 v_sphere_radiance;
out float v_on_sphere;

void main() {
  Atmosphere atmosphere = block_atmosphere();
  int row = gl_VertexID / (u_columns + 1);
  int column = gl_VertexID - row * (u_columns + 1);
  vec2 corner = min(vec2(column, row) * float(u_cell), u_viewport);
  ivec2 pixel = ivec2(min(corner, u_viewport - 1.0));
  vec2 ndc = corner / u_viewport * 2.0 - 1.0;
  vec3 ray = ray_at_ndc(ndc);
  float ray_scale = length(ray);
  vec3 dir = ray / ray_scale;
  vec3 camera = oneil_camera(atmosphere);
  float t_surface = surface_distance(pixel, ray_scale);
  if (t_surface == kFar) dir = over_the_lifted_horizon(atmosphere, camera, length(u_camera), dir);
  float t_ground;
  bool ground = ray_hits_ground(atmosphere, camera, dir, t_ground);
  v_sky = t_surface == kFar && !ground ? 1.0 : 0.0;
  float distance = t_surface == kFar ? t_ground : t_surface;
  v_inverse_distance = v_sky > 0.0 ? 0.0 : 1.0 / distance;
  v_on_sphere = ground ? 1.0 : 0.0;
  v_sphere_radiance =
      ground ? oneil_sphere_radiance(atmosphere, camera + t_ground * dir) : vec3(0.0);
  // A vertex over open sky serves no pixel (every triangle with one sends
  // its pixels to their own rays): no samples, so that a batch of them in
  // the vertex shader's SIMD leaves the loop at once.
  oneil_ray(atmosphere, camera, dir, t_surface, v_sky > 0.0 ? 0 : SAMPLES, v_rayleigh, v_mie,
            v_transmittance);
  gl_Position = vec4(ndc, 0.0, 1.0);
}
