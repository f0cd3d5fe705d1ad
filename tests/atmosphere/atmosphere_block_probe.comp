// Writes the Atmosphere that block_atmosphere() (atmosphere/shaders/
// atmosphere_block.glsl) unpacks from the bound block, field by field in
// the struct's order, as floats: tests/atmosphere/atmosphere_block_gl_test.cpp
// compares them with the model's shared Atmosphere.
#include "atmosphere/shaders/atmosphere_block.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = 1) writeonly buffer Outputs { float outputs[]; };

int put(int i, float x) {
  outputs[i] = x;
  return i + 1;
}

int put3(int i, vec3 v) {
  return put(put(put(i, v.x), v.y), v.z);
}

int put_profile(int i, DensityProfile p) {
  for (int k = 0; k < 2; ++k) {
    DensityLayer l = p.layers[k];
    i = put(put(put(put(put(i, l.width), l.exp_term), l.exp_scale), l.linear_term),
            l.constant_term);
  }
  return i;
}

void main() {
  Atmosphere a = block_atmosphere();
  int i = put(0, a.bottom_radius);
  i = put(i, a.top_radius);
  i = put3(i, a.solar_irradiance);
  i = put(i, a.sun_angular_radius);
  i = put3(i, a.rayleigh_scattering);
  i = put_profile(i, a.rayleigh_density);
  i = put3(i, a.mie_scattering);
  i = put3(i, a.mie_extinction);
  i = put(i, a.mie_g);
  i = put_profile(i, a.mie_density);
  i = put3(i, a.absorption_extinction);
  i = put_profile(i, a.absorption_density);
  i = put3(i, a.ground_albedo);
  i = put(i, a.mie_phase_hg);
}
