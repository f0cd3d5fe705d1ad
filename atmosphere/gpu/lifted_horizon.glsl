// Lowlands and hollows put the camera below the atmosphere's bottom sphere,
// and every technique lifts it onto the sphere. A ray over which nothing
// was drawn has cleared the terrain's horizon, but from the lifted camera
// it may still meet the sphere just below the sphere's own horizon: a
// ground the terrain does not have, drawn as a dark line along the horizon.
// Such a ray is raised to just above that horizon, to the sky that lies
// beyond the terrain. camera: the lifted camera; r_camera: its distance
// from the centre before the lift; dir: unit.
//
// The ray is raised kLiftedHorizonMargin in cosine above the horizon: with
// 1e-4, float rounding in the ray-sphere tests (r^2 of 1e13 m^2 against a
// margin of 1e6) sent one pixel in ten back into the sphere, dark specks
// along the terrain's silhouette.
const float kLiftedHorizonMargin = 1e-3;
vec3 over_the_lifted_horizon(Atmosphere atmosphere, vec3 camera, float r_camera, vec3 dir) {
  if (r_camera >= atmosphere.bottom_radius + 1.0) return dir;
  vec3 up = camera / length(camera);
  float mu_horizon = -safe_sqrt(1.0 - (atmosphere.bottom_radius / length(camera)) *
                                          (atmosphere.bottom_radius / length(camera)));
  float mu = dot(dir, up);
  if (mu >= mu_horizon + kLiftedHorizonMargin) return dir;
  vec3 across = dir - mu * up;
  float across_length = length(across);
  vec3 horizontal = across_length > 1e-6
                        ? across / across_length
                        : normalize(cross(up, abs(up.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0)));
  float raised = mu_horizon + kLiftedHorizonMargin;
  return raised * up + safe_sqrt(1.0 - raised * raised) * horizontal;
}
