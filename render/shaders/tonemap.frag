// Exposure, then the tone map (Narkowicz's 2015 fit of the ACES filmic
// curve and the sRGB transfer function) into an 8-bit target.
#define Real float
#define Real3 vec3
#include "core/shaders/tone_map.glsl"

in vec2 v_ndc;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_hdr;
uniform float u_exposure;
// 1: the exposure is the one auto_exposure.comp measured on this frame.
uniform int u_auto_exposure;
layout(std430, binding = 3) readonly buffer ExposureBlock {
  float measured_exposure;
  float mean_luminance;
};
// 1: the target already holds display values (a technique's own mapping).
uniform int u_display_values;
// The glare (render/glare.cpp): the sum of its levels, each one
// octave of the eye's scattered light, and the share of the light each
// takes; 0: no glare.
layout(binding = 1) uniform sampler2D u_glare;
uniform float u_glare_per_octave;
uniform int u_glare_octaves;

// Jimenez 2014, interleaved gradient noise: a fixed per-pixel pattern in
// [0, 1), so that dithered frames stay identical run to run.
float dither_noise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

void main() {
  vec3 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb;
  if (u_glare_per_octave > 0.0) {
    // What the glare spreads around is taken from where it came: a scene
    // without bright points keeps its brightness.
    vec3 glare = texture(u_glare, gl_FragCoord.xy / vec2(textureSize(u_hdr, 0))).rgb;
    hdr = (1.0 - float(u_glare_octaves) * u_glare_per_octave) * hdr + u_glare_per_octave * glare;
  }
  float exposure = u_auto_exposure != 0 ? measured_exposure : u_exposure;
  vec3 color = u_display_values != 0 ? clamp(hdr, 0.0, 1.0) : tone_map(hdr * exposure);
  // Half a step of the 8-bit target either way, after tone mapping: smooth
  // skies quantise into noise finer than the eye, not into bands.
  color += (dither_noise(gl_FragCoord.xy) - 0.5) / 255.0;
  o_color = vec4(color, 1.0);
}
