// The sky dome: a mesh on the atmosphere's top sphere whose vertices lie
// along rays from the camera, u_rings rings by u_segments around the
// camera's vertical, over exactly the directions whose rays miss the ground:
// from inside the atmosphere, from the horizon's dip up to the zenith
// (rings crowded toward the horizon, where the sky changes fastest); from
// outside, the ring between the planet's disk and the atmosphere's limb.
// Each vertex sums the single scattering along its ray (O'Neil's "sky from
// atmosphere" and "sky from space"); the fragments apply the phases.
#include "atmosphere/gpu/oneil/oneil_common.glsl"

uniform int u_rings;
uniform int u_segments;
uniform vec3 u_up, u_east, u_north;  // the camera's vertical and two horizontals
uniform int u_outside;
uniform mat3 u_ndc_from_ray;  // the inverse of u_ray_from_ndc

out vec3 v_rayleigh;
out vec3 v_mie;
out vec3 v_transmittance;

void main() {
  Atmosphere atmosphere = block_atmosphere();
  vec3 camera = oneil_camera(atmosphere);
  float r = length(camera);
  int ring = gl_VertexID / (u_segments + 1);
  int segment = gl_VertexID - ring * (u_segments + 1);
  float s = float(ring) / float(u_rings);
  float azimuth = 2.0 * kPi * float(segment) / float(u_segments);
  vec3 horizontal = cos(azimuth) * u_east + sin(azimuth) * u_north;
  vec3 dir, drawn;
  if (u_outside == 0) {
    // Elevation from the dip of the ground's horizon to the zenith.
    float dip = acos(clamp(atmosphere.bottom_radius / r, 0.0, 1.0));
    float elevation = -dip + (0.5 * kPi + dip) * s * s;
    dir = cos(elevation) * horizontal + sin(elevation) * u_up;
    // The lowest ring is drawn a little below the horizon, so that no
    // pixel between its chords and the horizon is left out; the pixels
    // whose rays meet the ground are the grid's, and discarded here. A
    // camera lifted out of a hollow sees sky over the terrain's silhouette
    // well below the sphere's horizon (those rays are raised onto it:
    // lifted_horizon.glsl), and the ring is drawn down to near the nadir.
    bool lifted = length(u_camera) < atmosphere.bottom_radius + 1.0;
    float drop = lifted ? 0.5 * kPi - 0.05 - dip : 0.01;
    float drawn_elevation = ring == 0 ? elevation - drop : elevation;
    drawn = cos(drawn_elevation) * horizontal + sin(drawn_elevation) * u_up;
    dir = normalize(dir + 1e-4 * u_up);
    if (ring == 0) dir = over_the_lifted_horizon(atmosphere, camera, length(u_camera), dir);
  } else {
    // Angle from the nadir, from the planet's disk to the atmosphere's
    // limb, crowded toward both edges.
    float psi_ground = asin(clamp(atmosphere.bottom_radius / r, 0.0, 1.0));
    float psi_top = asin(clamp(atmosphere.top_radius / r, 0.0, 1.0));
    float psi = psi_ground + (psi_top - psi_ground) * (0.5 - 0.5 * cos(kPi * s));
    // Drawn a little beyond both edges, evaluated just off the ground.
    float drawn_psi = ring == 0 ? psi * 0.999 : ring == u_rings ? psi * 1.001 : psi;
    float ray_psi = ring == 0 ? psi * 1.0001 : psi;
    dir = cos(ray_psi) * -u_up + sin(ray_psi) * horizontal;
    drawn = cos(drawn_psi) * -u_up + sin(drawn_psi) * horizontal;
  }
  oneil_ray(atmosphere, camera, dir, kFar, SAMPLES, v_rayleigh, v_mie, v_transmittance);
  // The ray's direction in the camera's projective frame: x, y over z are
  // its NDC (u_ray_from_ndc maps NDC to rays); behind the camera, z < 0
  // and GL clips it.
  vec3 q = u_ndc_from_ray * drawn;
  gl_Position = vec4(q.xy, 0.0, q.z);
}
