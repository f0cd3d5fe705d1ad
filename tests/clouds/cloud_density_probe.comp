// Evaluates the shared cloud functions in float for the agreement test
// (tests/clouds/cloud_density_gl_test.cpp): one planet-centred point and a
// scattering cosine per invocation; density, weather and phase out.
#include "clouds/shaders/cloud_block.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform vec4 u_layer[3];
uniform int u_count;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_count) return;
  CloudLayer l = CloudLayer(u_layer[0].x, u_layer[0].y, u_layer[0].z, u_layer[0].w,
                            u_layer[1].x, u_layer[1].y, u_layer[1].z, u_layer[1].w,
                            u_layer[2].x, u_layer[2].y, u_layer[2].z, u_layer[2].w);
  vec3 p = inputs[i].xyz;
  vec2 weather = cloud_weather(l, p);
  outputs[i] = vec4(cloud_density(l, p), weather, cloud_phase(l.droplet_diameter_um, inputs[i].w));
}
