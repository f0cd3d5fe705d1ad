// Terrain lit by the sun through the atmosphere (Lambert's law; Hapke's
// where the body has regolith; Fresnel and the sun's glint on the open
// sea), where the terrain's horizon does not hide it, plus the sky's
// ambient, plus the lights of the night side where the body has a map of
// them: the radiance leaving the ground toward the camera. The atmosphere
// pass adds what lies between (aerial perspective) and dims this by the
// air's transmittance, lights included.
#include "atmosphere/shaders/surface_lighting.glsl"
#include "terrain/shaders/regolith.glsl"
#include "terrain/shaders/sea_brdf.glsl"
#include "terrain/shaders/ground_material.glsl"
#include "terrain/gpu/shaders/ground_detail.glsl"

in vec3 v_normal_body;
in vec4 v_albedo;  // alpha: tile_mesh.cpp's pack_albedo
in vec3 v_position_body;
in float v_eye_distance;
in float v_over_sea;
in vec3 v_sun_transmittance;
in vec3 v_sky_irradiance;
in float v_sun_over_horizon;
in vec3 v_rel_eye;
in vec3 v_tile_offset;  // from the tile's centre, unmorphed: where the detail is sampled
layout(location = 0) out vec4 o_radiance;
// How far the ground lies below the datum, metres (0 where it does not):
// the air in front of it goes down to it (sky_pixel.glsl). A drawn sea
// lies on the datum.
layout(location = 1) out float o_ground_below;

uniform vec3 u_sun_dir_body;
uniform vec3 u_sun_irradiance;
// Half the width of a shadow's edge in sun elevation, radians: the sun's
// disc, or the horizon's coding where that is coarser.
uniform float u_penumbra;

// The body's imagery (terrain/surface_maps.h), equirectangular: the day
// image's colours as stored with its land mask in alpha, and the night's
// lights as sRGB radiance.
uniform int u_has_day_map;
uniform int u_has_night_map;
layout(binding = 13) uniform sampler2D u_day_map;
layout(binding = 14) uniform sampler2D u_night_map;
uniform float u_geodetic_k;     // (1 - flattening)^2
uniform vec2 u_map_fade;        // eye distances over which the day image takes over, metres
uniform float u_night_radiance; // of a white night pixel, W m^-2 sr^-1 nm^-1
uniform float u_map_texel_m;    // a pixel of the images on the ground, metres
uniform int u_has_sea;
uniform int u_over_datum;       // 1: v_over_sea is the height over the datum (no sea)
uniform vec3 u_ocean_albedo;    // the palette's open sea: the light from below its surface
uniform float u_sea_slope_variance;  // Cox and Munk's sigma^2 for the body's wind
uniform vec3 u_camera_body;         // float: the sea's point to 0.5 m, its normal to 1e-7
uniform float u_sea_radius;          // the datum's equatorial radius plus the sea's level, metres
// Regolith's law (terrain/regolith.h), where u_regolith is 1: w, xi, b0,
// h; the roughness's mean slope; the law's normal albedo.
uniform int u_regolith;
uniform vec4 u_regolith_law;
uniform float u_regolith_theta_bar;
uniform float u_regolith_normal_albedo;
// 1: Earth's materials (ground_material.glsl) in the day image's far
// field, and the procedural detail (ground_detail.glsl) on land.
uniform int u_materials;

// Longitude and geodetic latitude as the images' coordinates.
vec2 map_uv(vec3 p) {
  float lon = atan(p.y, p.x);
  float lat = atan(p.z, u_geodetic_k * length(p.xy));
  return vec2(lon / (2.0 * kPi) + 0.5, 0.5 - lat / kPi);
}

// The day image's display colours as albedo: 0.42 c^1.2 puts the Sahara
// near 0.4, forest near 0.07 in green and open ocean near 0.06 in blue;
// white (ice, cloud-free snow) rises to 0.85.
vec3 day_albedo(vec3 c) {
  vec3 a = max(0.42 * pow(c, vec3(1.2)), vec3(0.01));
  float white = smoothstep(0.8, 0.95, min(c.r, min(c.g, c.b)));
  return mix(a, 0.85 * c, white);
}

// The sun's term for ground that reflects as regolith, in the place of
// Lambert's cos(i): pi r / A_n, so that the palette's albedo (the normal
// albedo A, regolith.h) over pi times it is A / A_n times Hapke's r.
float regolith_sun_term(vec3 n) {
  RegolithLaw law = RegolithLaw(u_regolith_law.x, u_regolith_law.y, u_regolith_law.z,
                                u_regolith_law.w, u_regolith_theta_bar);
  vec3 to_eye = -normalize(v_rel_eye);
  float r = regolith_reflectance(law, dot(n, u_sun_dir_body), dot(n, to_eye),
                                 dot(u_sun_dir_body, to_eye));
  return kPi * r / u_regolith_normal_albedo;
}

// The radiance the open sea sends toward the eye (sea_brdf.glsl): the
// light from below its surface (the palette's or the image's water
// albedo, lit as the ground is, by `irradiance`) through the share the
// surface lets out, 1 - Fresnel; the sky it mirrors, Fresnel times the
// sky's mean radiance (its irradiance `sky` over pi: the technique's own
// sky, but not yet its radiance in the mirrored direction); and the
// sun's glint.
vec3 sea_radiance(vec3 water_albedo, vec3 irradiance, vec3 sky, vec3 sun_transmittance,
                  float sun_visible) {
  // The mean surface is the datum's ellipsoid, which the tile's flat
  // facets cut below: the view ray meets it nearer than the fragment, by
  // what the facet sags over the ray's steepness (to first order). At a
  // grazing view from 400 km the facet's own normal tilted the glint's
  // tail by 2.5 %.
  vec3 view = -normalize(v_rel_eye);
  // The point drawn, morph included (v_position_body leaves it out).
  vec3 p = u_camera_body + v_rel_eye;
  vec3 up = normalize(p);
  float datum = u_sea_radius / length(vec3(up.xy, up.z / sqrt(u_geodetic_k)));
  p += view * ((datum - length(p)) / max(dot(up, view), 0.05));
  vec3 n = normalize(vec3(p.xy, p.z / u_geodetic_k));
  float fresnel = sea_fresnel(dot(n, view));
  vec3 glint = u_sun_irradiance * sun_transmittance *
               (sun_visible * sea_glint(n, view, u_sun_dir_body, u_sea_slope_variance));
  return (1.0 - fresnel) * water_albedo / kPi * irradiance +
         fresnel * u_sun_irradiance * sky / kPi + glint;
}

void main() {
  vec3 n = normalize(v_normal_body);
  // The detail's octaves fade by the pixel's footprint, taken from the
  // tile's small offsets (the body-frame position is 0.5 m coarse).
  float detail_footprint = max(length(dFdx(v_tile_offset)), length(dFdy(v_tile_offset)));
  vec4 detail = vec4(1.0, 0.0, 0.0, 0.0);
  // Within 2 km of the eye (ground_detail.glsl): farther, the vertices'
  // fields and the day image carry the ground.
  float detail_share = 1.0 - smoothstep(1000.0, 2000.0, v_eye_distance);
  if (u_materials != 0 && detail_share > 0.0) {
    detail = mix(vec4(1.0, 0.0, 0.0, 0.0), ground_detail(v_tile_offset, detail_footprint),
                 detail_share);
    // The detail's height field tilts the normal by its gradient along the
    // ground; snow (the bright ground) lies smoother, at a third of it.
    float smooth_snow = 1.0 - 0.67 * smoothstep(0.5, 0.8, dot(v_albedo.rgb, vec3(1.0 / 3.0)));
    vec3 tilt = smooth_snow * (detail.yzw - dot(detail.yzw, n) * n);
    n = normalize(n - tilt);
  }
  // The share of the sun's disc above the horizon: interpolated per
  // fragment, the shadow's edge falls between vertices.
  float sun_visible = smoothstep(-u_penumbra, u_penumbra, v_sun_over_horizon);
  float cos_sun = max(dot(n, u_sun_dir_body), 0.0) * sun_visible;
  if (u_regolith != 0) cos_sun = regolith_sun_term(n) * sun_visible;
  // Multisampled, a pixel whose centre lies outside a triangle that covers
  // some of its samples takes the values extrapolated to its centre, far
  // outside the triangle's own where it is seen edge-on (a smooth slope's
  // silhouette from 2 m; over ETOPO5's Alps an edge pixel's albedo came out
  // 24 and its radiance 3.37 against 0.18 from 16 rays): each is held to
  // what it can be. (Centroid interpolation did not help on llvmpipe.)
  vec3 transmittance = clamp(v_sun_transmittance, 0.0, 1.0);
  vec3 sky = clamp(v_sky_irradiance, 0.0, 1.0);
  vec3 irradiance = u_sun_irradiance * (transmittance * cos_sun + sky);

  vec3 ground_albedo = clamp(v_albedo.rgb * detail.x, 0.0, 1.0);
  vec3 albedo = ground_albedo;
  // The shares of land and of open water in the pixel, and their albedos.
  vec3 land_albedo = ground_albedo;
  vec3 water_albedo = u_ocean_albedo;
  float water = 0.0;
  // The sea where the ground's height over it, interpolated over the
  // triangle, is negative: the coastline crosses triangles along a line
  // that the next finer tiles only refine, its edge a pixel wide.
  float sea = 0.0;
  if (u_has_sea != 0) {
    float edge = max(fwidth(v_over_sea), 1e-3);
    sea = 1.0 - smoothstep(-0.5 * edge, 0.5 * edge, v_over_sea);
    albedo = mix(albedo, u_ocean_albedo, sea);
    water = sea;
  }
  vec3 emitted = vec3(0.0);
  // The mipmap level from the fragment's footprint on the ground: the
  // longitude's wrap would break the texture coordinates' derivatives.
  // (Derivatives outside the branch below, which pixels of a quad take
  // apart.)
  float footprint = max(length(dFdx(v_position_body)), length(dFdy(v_position_body)));
  float fade = smoothstep(u_map_fade.x, u_map_fade.y, v_eye_distance);
  // The sun's height over the ground, for the night's lights.
  float sun_sin = dot(normalize(v_position_body), u_sun_dir_body);
  // Lit as the sun sets, out by the time it stands 1 degree up.
  float lights_on = u_has_night_map != 0 ? 1.0 - smoothstep(-0.05, 0.017, sun_sin) : 0.0;
  // Near the camera on land by day the images add nothing (the mixes
  // below take none of them): most of a view from the ground, and most
  // of the images' cost on a GL that fetches texels in software.
  if (u_has_day_map != 0 && (fade > 0.0 || sea > 0.0 || lights_on > 0.0)) {
    vec2 uv = map_uv(v_position_body);
    float lod = log2(max(footprint / u_map_texel_m, 1e-6));
    vec4 day = textureLod(u_day_map, uv, lod);
    // The image's land, turned as the heights turn it (procedural_height.cpp).
    float land = smoothstep(0.3, 0.7, day.a);
    vec3 image = day_albedo(day.rgb);
    // Earth's land in the image: its materials' albedos (ground_material.glsl).
    vec3 image_land = u_materials != 0 ? image_material(day.rgb).albedo : image;
    // Near the camera, the ground's own: the sea above, the palette's
    // colours on land (alpha 0.5 + half the map's cover). Beyond the
    // fade, the image's: its water and land where it draws them (the
    // heights follow its mask only within its 20 km pixels), with rock and
    // snow as the palette has them.
    float land_cover = clamp(2.0 * v_albedo.a - 1.0, 0.0, 1.0);
    land_albedo = mix(ground_albedo, image_land, land_cover * fade);
    water_albedo = mix(u_ocean_albedo, image, 1.0 - land);
    water = u_has_sea != 0 ? mix(sea, 1.0 - land, fade) : 0.0;
    albedo = mix(land_albedo, water_albedo, mix(sea, 1.0 - land, fade));
    if (lights_on > 0.0) {
      emitted = lights_on * u_night_radiance * textureLod(u_night_map, uv, lod).rgb;
    }
  }
  o_radiance = vec4(albedo / kPi * irradiance + emitted, 1.0);
  if (water > 0.0) {
    vec3 sea_surface = sea_radiance(water_albedo, irradiance, sky, transmittance, sun_visible);
    o_radiance.rgb = mix(land_albedo / kPi * irradiance, sea_surface, water) + emitted;
  }
  o_ground_below = u_over_datum != 0 ? min(v_over_sea, 0.0) : 0.0;
}
