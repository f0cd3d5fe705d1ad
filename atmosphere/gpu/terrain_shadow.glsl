// The terrain's shadow in the air, from the frame's shadow-height field
// (terrain/sun_shadow_field.h): a point of the air is in the terrain's
// shadow when its altitude lies below the field's height over its place on
// the field's gnomonic patch. The sun comes in over u_shadow_softness metres
// of altitude (its disc, and the field's cells); toward the patch's edge
// the shadow fades out, and u_shadow_strength (0 to 1) fades all of it (no
// field: 0). Included before the technique's integrals, which call
// terrain_sun_visibility; without TERRAIN_SHADOWS the sun is never hidden.
#ifdef TERRAIN_SHADOWS
layout(binding = 9) uniform sampler2D u_shadow_heights;
uniform vec3 u_shadow_up;
uniform vec3 u_shadow_east;
uniform vec3 u_shadow_north;
uniform vec2 u_shadow_plane;  // the bottom radius, and the patch's half side
uniform float u_shadow_strength;
uniform float u_shadow_softness;  // kTerrainShadowSoftness

float terrain_sun_visibility(vec3 p) {
  float r = length(p);
  vec3 q = p / r;
  float c = dot(q, u_shadow_up);
  vec2 xy = vec2(dot(q, u_shadow_east), dot(q, u_shadow_north)) * (u_shadow_plane.x / max(c, 1e-3));
  float edge = max(abs(xy.x), abs(xy.y)) / u_shadow_plane.y;
  float weight = (1.0 - smoothstep(0.85, 1.0, edge)) * step(1e-3, c) * u_shadow_strength;
  float h = texture(u_shadow_heights, xy / (2.0 * u_shadow_plane.y) + 0.5).r;
  float lit = clamp((r - u_shadow_plane.x - h) / u_shadow_softness + 0.5, 0.0, 1.0);
  return 1.0 - (1.0 - lit) * weight;
}
#else
float terrain_sun_visibility(vec3 p) { return 1.0; }
#endif
