// The surfaces' coverage, drawn multisampled (render/surface_antialiasing.h):
// each sample's depth, and how far the ground lies below the datum there
// (terrain.frag's o_ground_below), without light. The light is terrain.frag's,
// drawn once a pixel: on a GL that shades each sample (llvmpipe) this is
// what a sample costs.
in float v_over_sea;
layout(location = 0) out float o_ground_below;

uniform int u_over_datum;  // 1: v_over_sea is the height over the datum (no sea)

void main() { o_ground_below = u_over_datum != 0 ? min(v_over_sea, 0.0) : 0.0; }
