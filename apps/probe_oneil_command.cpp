// planet probe oneil-fit: the oneil technique's scale functions for a body,
// fitted to its Rayleigh and Mie scale heights, with their worst errors of
// optical depth, beside the chapter's fixed polynomial's.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "atmosphere/math/oneil_math.h"
#include "sim/body.h"

#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>

namespace planet::apps {

namespace {

struct ProbeOneilArgs {
  std::string planet = "earth";
};

void print_error(const char* what, const oneil::ScaleError& e) {
  std::printf(
      "  %-28s worst relative %7.3f %% (at h = %.4g km, mu = %+.4f); worst absolute "
      "%.3g of the vertical column\n",
      what, 100 * e.worst_relative, e.worst_h / 1e3, e.worst_mu, e.worst_of_vertical);
}

void run(const ProbeOneilArgs& args) {
  Body body = load_body(find_body_file(args.planet));
  AtmosphereModel model = load_atmosphere(body);
  oneil::BodyScales fitted = oneil::fit_body_scales(model);
  shared::Atmosphere a = shared::to_shared(model);
  double thickness = model.top_radius - model.bottom_radius;
  std::printf("%s: atmosphere %.4g km thick over a %.6g km radius\n", body.name.c_str(),
              thickness / 1e3, model.bottom_radius / 1e3);
  std::printf(
      "fitted form: column = V(h) G(h, mu) exp(sum c[i][j] v^(i+1) z^j), i < %d, j < %d "
      "(atmosphere/shaders/oneil_functions.glsl)\n",
      oneil::kOneilXTerms, oneil::kOneilYTerms);
  const std::pair<const char*, const oneil::OneilScale*> parts[] = {{"Rayleigh", &fitted.rayleigh},
                                                                    {"Mie", &fitted.mie}};
  for (const auto& [name, scale] : parts) {
    std::printf("\n%s: scale height %.6g km, %.4g of the thickness\n", name,
                scale->scale_height / 1e3, scale->scale_height / thickness);
    for (int i = 0; i < oneil::kOneilXTerms; ++i) {
      std::printf("  c[%d] =", i);
      for (int j = 0; j < oneil::kOneilYTerms; ++j) {
        std::printf(" %+.8e", scale->c[i * oneil::kOneilYTerms + j]);
      }
      std::printf("\n");
    }
    print_error("fitted:", name == std::string("Mie") ? fitted.mie_error : fitted.rayleigh_error);
    print_error("chapter's polynomial:",
                oneil::measure_scale_error(a, oneil::chapter_scale(scale->scale_height)));
  }
  // The chapter's own case: H a quarter of the thickness, the thickness
  // 2.5 % of the radius, where its polynomial was fitted.
  shared::Atmosphere own = a;
  own.top_radius = own.bottom_radius * 1.025;
  double h_own = 0.25 * (own.top_radius - own.bottom_radius);
  std::printf("\nthe chapter's own case (thickness 2.5 %% of the radius, H a quarter of it):\n");
  print_error("chapter's polynomial:",
              oneil::measure_scale_error(own, oneil::chapter_scale(h_own)));
  print_error("fitted:", oneil::measure_scale_error(own, oneil::fit_scale(own, h_own)));
}

}  // namespace

void add_probe_oneil_command(CLI::App& probe) {
  auto args = std::make_shared<ProbeOneilArgs>();
  CLI::App* cmd = probe.add_subcommand(
      "oneil-fit", "The oneil technique's scale functions for a body, and their errors");
  cmd->add_option("--planet,--body", args->planet, body_option_help())->capture_default_str();
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
