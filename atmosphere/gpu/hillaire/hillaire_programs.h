#pragma once
// The Hillaire technique's programs, each with its defines written once:
// the sky pass's variants (hillaire_sky.frag) and the scattering orders'
// and space's in a table each (gl/program_variants.h), from which every
// compile takes them.
#include "gl/program.h"
#include "gl/program_variants.h"
#include "gl/schedule.h"

namespace planet {

// What the programs compile with, from the technique's settings.
struct HillaireShaderOptions {
  // The view's passes take the forward gain from its LUT (our orders); the
  // paper's form goes without, as the paper has it.
  bool forward_gain_lut = true;
  bool terrain_shadows = true;
  int sky_view_steps = 30, per_pixel_steps = 40, aerial_substeps = 2, space_view_steps = 40;
};

struct HillairePrograms {
  explicit HillairePrograms(const HillaireShaderOptions& options, Schedule schedule);

  Program transmittance, multiple_scattering, orders_sum, forward_gain, sky_view, aerial,
      march_tiles;
  // scattering_orders.comp: "first" (from the sun) and "next" (from the
  // order before). Two programs rather than a uniform: llvmpipe runs both
  // sides of a branch on a uniform, which made the pass 1.7 times slower.
  ProgramVariants orders;
  // space.frag: "lit" (with the sun's disk) and "unlit".
  ProgramVariants space;
  // space_view_lut.comp: "space_view_lut", compiled when first marched.
  ProgramVariants space_view;
  // hillaire_sky.frag's variants: see hillaire_programs.cpp's table.
  ProgramVariants sky;
};

// The sky pass's variant for a frame on the per-pixel path alone: without
// the LUT path, for grey Mie or not, with the terrain's shadow or not.
std::string per_pixel_sky_variant(bool grey_mie, bool shadow);

}  // namespace planet
