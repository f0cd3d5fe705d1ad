#include "atmosphere/model.h"

#include "atmosphere/atmosphere_inputs.h"
#include "core/error.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

const char* to_string(MiePhase phase) {
  return phase == MiePhase::kHenyeyGreenstein ? "henyey_greenstein" : "cornette_shanks";
}

double density_at(const DensityProfile& profile, double altitude) {
  const DensityLayer& l =
      altitude < profile.layers[0].width ? profile.layers[0] : profile.layers[1];
  // The exponential only where the layer has one: this runs millions of
  // times a second in the reference's path tracer.
  double e = l.exp_term != 0.0 ? l.exp_term * std::exp(l.exp_scale * altitude) : 0.0;
  double d = e + l.linear_term * altitude + l.constant_term;
  return std::clamp(d, 0.0, 1.0);
}

namespace {

glm::dvec3 rgb(JsonObject& o, const std::string& key) {
  auto v = o.numbers(key, 3, 0.0, 1.0);  // 1/m: even 50x Earth is far below 1
  return {v[0], v[1], v[2]};
}

DensityProfile parse_density(JsonObject d, double thickness) {
  DensityProfile p{};
  std::string type = d.string("type");
  if (type == "exponential") {
    double H = d.number("scale_height_m", 1.0, 1e7);
    p.layers[1] = {0.0, 1.0, -1.0 / H, 0.0, 0.0};
  } else if (type == "tent") {
    // A triangle of height 1 centred at `center` with base `width`: two
    // linear layers meeting at the centre.
    double c = d.number("center_m", 0.0, thickness);
    double w = d.number("width_m", 1.0, 2.0 * thickness);
    double half = 0.5 * w;
    // Density outside [0, thickness] would be silently cut off by the shell.
    if (c - half < 0.0 || c + half > thickness) {
      d.fail("width_m", fmt::format("the tent [{:g}, {:g}] m must lie inside the atmosphere "
                                    "[0, {:g}] m",
                                    c - half, c + half, thickness));
    }
    p.layers[0] = {c, 0.0, 0.0, 1.0 / half, 1.0 - c / half};
    p.layers[1] = {0.0, 0.0, 0.0, -1.0 / half, 1.0 + c / half};
  } else if (type == "uniform") {
    p.layers[1] = {0.0, 0.0, 0.0, 0.0, 1.0};
  } else {
    d.fail("type", fmt::format("'{}' is not a density profile (exponential, tent, uniform)", type));
  }
  d.finish();
  return p;
}

AtmosphereComponent parse_component(JsonObject c, const std::string& name, PhaseKind phase,
                                    double thickness) {
  AtmosphereComponent out;
  c.string_or("source", "");  // where the values come from, for the reader
  out.name = name;
  out.phase = phase;
  out.scattering = c.has("scattering") ? rgb(c, "scattering") : glm::dvec3(0.0);
  out.absorption = c.has("absorption") ? rgb(c, "absorption") : glm::dvec3(0.0);
  if (c.has("extinction")) {
    // Mie data is often given as scattering and extinction; absorption is
    // their difference and must not be negative.
    glm::dvec3 extinction = rgb(c, "extinction");
    glm::dvec3 absorption = extinction - out.scattering;
    if (glm::any(glm::lessThan(absorption, glm::dvec3(-1e-15)))) {
      c.fail("extinction", "must not be below scattering");
    }
    out.absorption = glm::max(absorption, glm::dvec3(0.0));
  }
  out.density = parse_density(c.object("density"), thickness);
  c.finish();
  return out;
}

// A coefficient at every spectral sample: either a table (one value per
// wavelength, 1/m) or a power law {"reference_nm", "value", "exponent"},
// value * (reference_nm / lambda)^exponent: Rayleigh's lambda^-4, or an
// Angstrom exponent for aerosols.
std::vector<double> spectral_coefficient(JsonObject& s, const std::string& key,
                                         const std::vector<double>& wavelengths) {
  if (!s.has(key)) return std::vector<double>(wavelengths.size(), 0.0);
  if (s.raw(key).is_array()) return s.numbers(key, wavelengths.size(), 0.0, 1.0);
  JsonObject law = s.object(key);
  double reference_nm = law.number("reference_nm", 100.0, 3000.0);
  double value = law.number("value", 0.0, 1.0);
  double exponent = law.number("exponent", -10.0, 10.0);
  law.finish();
  std::vector<double> out;
  for (double lambda : wavelengths)
    out.push_back(value * std::pow(reference_nm / lambda, exponent));
  return out;
}

AtmosphereSpectrum parse_spectrum(JsonObject s) {
  s.string_or("source", "");
  AtmosphereSpectrum out;
  out.wavelengths_nm = s.number_list("wavelengths_nm", 360.0, 830.0);
  const auto& w = out.wavelengths_nm;
  if (w.size() < kMinSpectralSamples) {
    s.fail("wavelengths_nm",
           fmt::format("{} samples; at least {} are needed", w.size(), kMinSpectralSamples));
  }
  for (size_t i = 1; i < w.size(); ++i) {
    if (w[i] <= w[i - 1]) s.fail("wavelengths_nm", "must be strictly increasing");
  }
  if (w.front() > kSpectrumMinNm || w.back() < kSpectrumMaxNm) {
    s.fail("wavelengths_nm", fmt::format("[{:g}, {:g}] nm must span {:g}-{:g} nm", w.front(),
                                         w.back(), kSpectrumMinNm, kSpectrumMaxNm));
  }
  out.solar_irradiance = s.numbers("solar_irradiance", w.size(), 0.0, 1e6);
  out.rayleigh_scattering = spectral_coefficient(s, "rayleigh_scattering", w);
  out.mie_scattering = spectral_coefficient(s, "mie_scattering", w);
  if (s.has("mie_extinction")) {
    std::vector<double> extinction = spectral_coefficient(s, "mie_extinction", w);
    for (size_t i = 0; i < w.size(); ++i) {
      double absorption = extinction[i] - out.mie_scattering[i];
      if (absorption < -1e-15) {
        s.fail("mie_extinction",
               fmt::format("must not be below mie_scattering (at {:g} nm)", w[i]));
      }
      out.mie_absorption.push_back(std::max(absorption, 0.0));
    }
  } else {
    out.mie_absorption = spectral_coefficient(s, "mie_absorption", w);
  }
  out.absorber_absorption = spectral_coefficient(s, "absorber_absorption", w);
  s.finish();
  return out;
}

}  // namespace

AtmosphereModel with_scattering_scaled(AtmosphereModel m, double factor) {
  m.rayleigh.scattering *= factor;
  // Mie absorption is kept: the dense variants add scatterers, not absorbers.
  m.mie.scattering *= factor;
  if (m.spectrum) {
    for (double& v : m.spectrum->rayleigh_scattering) v *= factor;
    for (double& v : m.spectrum->mie_scattering) v *= factor;
  }
  return m;
}

AtmosphereModel with_absorption_scaled(AtmosphereModel m, double factor) {
  m.mie.absorption *= factor;
  m.absorber.absorption *= factor;
  if (m.spectrum) {
    for (double& v : m.spectrum->mie_absorption) v *= factor;
    for (double& v : m.spectrum->absorber_absorption) v *= factor;
  }
  return m;
}

namespace {

// Every coefficient, RGB and spectral, multiplied by `factor`.
AtmosphereModel with_coefficients_scaled(AtmosphereModel m, double factor) {
  return with_absorption_scaled(with_scattering_scaled(std::move(m), factor), factor);
}

// A profile whose heights are `factor` times as large.
DensityProfile stretched(DensityProfile p, double factor) {
  for (DensityLayer& l : p.layers) {
    l.width *= factor;
    l.exp_scale /= factor;
    l.linear_term /= factor;
  }
  return p;
}

// The integral of an exponential layer exp(-h / H) from 0 to `thickness`.
double column(double scale_height, double thickness) {
  return -scale_height * std::expm1(-thickness / scale_height);
}

}  // namespace

AtmosphereModel with_bottom_radius(AtmosphereModel m, double bottom_radius,
                                   bool absolute_thickness) {
  double thickness = m.top_radius - m.bottom_radius;
  if (absolute_thickness) {
    m.bottom_radius = bottom_radius;
    m.top_radius = bottom_radius + thickness;
    return m;
  }
  double k = bottom_radius / m.bottom_radius;
  m = with_coefficients_scaled(std::move(m), 1.0 / k);
  m.bottom_radius = bottom_radius;
  m.top_radius = bottom_radius + k * thickness;
  for (AtmosphereComponent* c : {&m.rayleigh, &m.mie, &m.absorber}) {
    c->density = stretched(c->density, k);
  }
  return m;
}

AtmosphereModel with_scale_heights_scaled(AtmosphereModel m, double factor) {
  double thickness = m.top_radius - m.bottom_radius;
  for (AtmosphereComponent* c : {&m.rayleigh, &m.mie}) {
    DensityLayer& l = c->density.layers[1];
    if (l.exp_term == 0.0 || l.exp_scale >= 0.0) continue;  // not an exponential
    double H = -1.0 / l.exp_scale;
    double keep = column(H, thickness) / column(factor * H, thickness);
    l.exp_scale /= factor;
    c->scattering *= keep;
    c->absorption *= keep;
    if (m.spectrum && c == &m.rayleigh) {
      for (double& v : m.spectrum->rayleigh_scattering) v *= keep;
    }
    if (m.spectrum && c == &m.mie) {
      for (double& v : m.spectrum->mie_scattering) v *= keep;
      for (double& v : m.spectrum->mie_absorption) v *= keep;
    }
  }
  return m;
}

AtmosphereModel with_rgb_at_spectral_samples(AtmosphereModel m, size_t i, size_t j, size_t k) {
  if (!m.spectrum) throw InputError("the atmosphere has no \"spectrum\" to draw three samples of");
  const AtmosphereSpectrum& s = *m.spectrum;
  size_t samples[3] = {i, j, k};
  for (int c = 0; c < 3; ++c) {
    size_t n = samples[c];
    if (n >= s.wavelengths_nm.size()) {
      throw InputError(fmt::format("spectral sample {} of {}", n, s.wavelengths_nm.size()));
    }
    m.wavelengths_nm[c] = s.wavelengths_nm[n];
    m.solar_irradiance[c] = s.solar_irradiance[n];
    m.rayleigh.scattering[c] = s.rayleigh_scattering[n];
    m.mie.scattering[c] = s.mie_scattering[n];
    m.mie.absorption[c] = s.mie_absorption[n];
    m.absorber.absorption[c] = s.absorber_absorption[n];
    if (!s.ground_albedo.empty()) m.ground_albedo[c] = s.ground_albedo[n];
  }
  return m;
}

AtmosphereModel parse_atmosphere(JsonObject a) {
  AtmosphereModel m;
  m.bottom_radius = a.number("bottom_radius_m", 1.0, 1e9);
  m.top_radius = a.number("top_radius_m", 1.0, 1e9);
  if (m.top_radius <= m.bottom_radius) {
    a.fail("top_radius_m",
           fmt::format("{:g} must be above bottom_radius_m {:g}", m.top_radius, m.bottom_radius));
  }
  double thickness = m.top_radius - m.bottom_radius;
  if (a.has("wavelengths_nm")) {
    auto w = a.numbers("wavelengths_nm", 3, 360.0, 830.0);
    m.wavelengths_nm = {w[0], w[1], w[2]};
  }
  m.sun_angular_radius = glm::radians(a.number("sun_angular_radius_deg", 1e-4, 10.0));
  if (a.has("inputs")) {
    for (const char* key : {"solar_irradiance", "mie_g", "mie_phase", "ground_albedo", "rayleigh",
                            "mie", "absorber", "spectrum"}) {
      if (a.has(key)) {
        a.fail(key, "give the coefficients or the inputs they derive from, not both");
      }
    }
    derive_atmosphere(a.object("inputs"), m);
  } else {
    auto e = a.numbers("solar_irradiance", 3, 0.0, 1e6);
    m.solar_irradiance = {e[0], e[1], e[2]};
    m.mie_g = a.number("mie_g", -0.999, 0.999);
    std::string phase = a.string_or("mie_phase", "cornette_shanks");
    if (phase == "henyey_greenstein") {
      m.mie_phase = MiePhase::kHenyeyGreenstein;
    } else if (phase != "cornette_shanks") {
      a.fail("mie_phase", fmt::format("'{}' is not a phase function (cornette_shanks, "
                                      "henyey_greenstein)",
                                      phase));
    }
    m.ground_albedo = glm::dvec3(a.number("ground_albedo", 0.0, 1.0));
    m.rayleigh =
        parse_component(a.object("rayleigh"), "rayleigh", PhaseKind::kRayleigh, thickness);
    if (m.rayleigh.absorption != glm::dvec3(0.0)) {
      // Molecules absorb through the separate absorber component (ozone).
      a.fail("rayleigh", "absorption must be zero; give it as the absorber component");
    }
    m.mie = parse_component(a.object("mie"), "mie", PhaseKind::kMie, thickness);
    if (a.has("absorber")) {
      m.absorber = parse_component(a.object("absorber"), "absorber", PhaseKind::kNone, thickness);
    }
    if (a.has("spectrum")) m.spectrum = parse_spectrum(a.object("spectrum"));
  }
  a.string_or("source", "");
  a.finish();
  return m;
}

AtmosphereModel load_atmosphere(const Body& body) {
  if (!body.has_atmosphere()) {
    throw InputError(fmt::format("{}: {} has no atmosphere", body.file.string(), body.name));
  }
  return parse_atmosphere(JsonObject(body.atmosphere, body.file.string(), "atmosphere"));
}

}  // namespace planet
