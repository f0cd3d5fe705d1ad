#include "atmosphere/gpu/hillaire/hillaire_programs.h"

#include <fmt/format.h>

namespace planet {

namespace {

constexpr const char* kFullscreen = "gl/shaders/fullscreen.vert";
constexpr const char* kHillaire = "atmosphere/gpu/hillaire/";

std::string hillaire_file(const char* name) { return std::string(kHillaire) + name; }

// A view pass's defines: its own, then the forward gain's.
std::vector<std::string> view_defines(const HillaireShaderOptions& options, std::string own) {
  std::vector<std::string> defines = {std::move(own)};
  if (options.forward_gain_lut) defines.push_back("FORWARD_GAIN_LUT 1");
  return defines;
}

// hillaire_sky.frag's variants (its head says what each part leaves out):
// the parts each compiles, and whether it takes the terrain's shadow
// where the settings do.
struct SkyVariant {
  const char* name;
  std::vector<std::string> parts;
  bool shadow = true;
  const char* vertex = kFullscreen;
};

const std::vector<SkyVariant>& sky_variants() {
  static const std::vector<SkyVariant> table = {
      // Every path, every pixel: the plain schedule's, and the software
      // schedule's where the view is not pruned.
      {"whole", {}},
      // The software schedule's LUT path in parts: the stencil's classes,
      // the open sky and the surfaces without the march and the sun's
      // disk, the march's tiles, and the whole shader again over the
      // sun's disk; with the disk for a lifted camera.
      {"classify", {"CLASSIFY 1"}},
      {"open_sky", {"NO_MARCH 1", "NO_SUN_DISK 1", "OPEN_SKY_ONLY 1"}},
      {"surfaces", {"NO_MARCH 1", "NO_SUN_DISK 1", "SURFACE_ONLY 1"}},
      {"tiles", {}, true, "atmosphere/gpu/hillaire/sky_tiles.vert"},
      {"unmarched", {"NO_MARCH 1"}},
      // The software schedule's per-pixel path alone.
      {"per_pixel", {"NO_LUT 1"}},
      {"per_pixel_grey_mie", {"NO_LUT 1", "GREY_MIE 1"}},
      {"per_pixel_unshadowed", {"NO_LUT 1"}, false},
      {"per_pixel_grey_mie_unshadowed", {"NO_LUT 1", "GREY_MIE 1"}, false},
      // From space, reading the space-view LUT: every pixel (plain), or
      // the open sky and the surfaces apart (software).
      {"space_view", {"NO_LUT 1", "SPACE_VIEW_LUT 1"}, false},
      {"space_view_open_sky", {"NO_LUT 1", "SPACE_VIEW_LUT 1", "OPEN_SKY_ONLY 1"}, false},
      {"space_view_surfaces", {"NO_LUT 1", "SPACE_VIEW_LUT 1", "SURFACE_ONLY 1"}, false},
  };
  return table;
}

ProgramVariants sky_programs(const HillaireShaderOptions& options) {
  std::vector<ProgramVariant> variants;
  for (const SkyVariant& v : sky_variants()) {
    std::vector<std::string> defines;
    if (v.shadow && options.terrain_shadows) defines.push_back("TERRAIN_SHADOWS 1");
    defines.insert(defines.end(), v.parts.begin(), v.parts.end());
    variants.push_back({v.name, defines, v.vertex});
  }
  return ProgramVariants(
      kFullscreen, hillaire_file("hillaire_sky.frag"),
      view_defines(options, fmt::format("PER_PIXEL_STEPS {}", options.per_pixel_steps)), variants);
}

std::vector<std::string> aerial_defines(const HillaireShaderOptions& options) {
  std::vector<std::string> defines =
      view_defines(options, fmt::format("AERIAL_SUBSTEPS {}", options.aerial_substeps));
  if (options.terrain_shadows) {
    defines.insert(defines.end(), {"TERRAIN_SHADOWS 1", "TERRAIN_SHADOW_LOSS 1"});
  }
  return defines;
}

}  // namespace

std::string per_pixel_sky_variant(bool grey_mie, bool shadow) {
  return std::string("per_pixel") + (grey_mie ? "_grey_mie" : "") + (shadow ? "" : "_unshadowed");
}

HillairePrograms::HillairePrograms(const HillaireShaderOptions& options, Schedule schedule)
    : transmittance(
          Program::compute(hillaire_file("transmittance_lut.comp"), {"TRANSMITTANCE_PASS 1"})),
      multiple_scattering(Program::compute(hillaire_file("multiple_scattering_lut.comp"),
                                           {"MULTIPLE_SCATTERING_PASS 1"})),
      orders_sum(Program::compute(hillaire_file("scattering_orders_sum.comp"),
                                  {"SCATTERING_ORDERS_PASS 1"})),
      forward_gain(Program::compute(hillaire_file("forward_gain_lut.comp"))),
      sky_view(Program::compute(
          hillaire_file("sky_view_lut.comp"),
          view_defines(options, fmt::format("SKY_VIEW_STEPS {}", options.sky_view_steps)))),
      aerial(Program::compute(hillaire_file("aerial_perspective.comp"), aerial_defines(options))),
      march_tiles(Program::compute(hillaire_file("sky_march_tiles.comp"))),
      orders("", hillaire_file("scattering_orders.comp"), {"SCATTERING_ORDERS_PASS 1"},
             {{"first", {"FIRST_ORDER 1"}}, {"next", {}}}),
      space(kFullscreen, "atmosphere/gpu/space.frag", {},
            {{"lit", {}}, {"unlit", {"NO_SUN_DISK 1"}}}),
      space_view(
          "", hillaire_file("space_view_lut.comp"),
          view_defines(options, fmt::format("SPACE_VIEW_STEPS {}", options.space_view_steps)),
          {{"space_view_lut", {}}}),
      sky(sky_programs(options)) {
  orders.compile({"first", "next"});
  space.compile({"lit", "unlit"});
  // The variants every frame near the ground may draw now; those of the
  // per-pixel path and of space when first drawn.
  if (schedule == Schedule::kSoftware) {
    sky.compile({"whole", "classify", "open_sky", "surfaces", "tiles"});
  } else {
    sky.compile({"whole"});
  }
}

}  // namespace planet
