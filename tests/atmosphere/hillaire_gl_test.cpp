// The hillaire technique on the GPU against the same integrals on the CPU
// (atmosphere/math/hillaire_math.h), and its frames checked for what a person
// must see: no NaN or Inf anywhere, no pop where its two paths meet.
#include "atmosphere/gpu/hillaire/hillaire_technique.h"
#include "atmosphere/math/hillaire_math.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

class HillaireGLTest : public ::testing::Test {
 protected:
  static constexpr int kSize = 64;

  void SetUp() override {
    // gtest_discover_tests passes only the first ENVIRONMENT entry: driver
    // errors must fail these tests, so the debug output is asked for here.
    setenv("PLANET_GL_DEBUG", "1", 1);
    context_ = GlContext::create_headless();
    body_ = load_body(data_dir() / "planets" / "earth.json");
    // These test the sky over a smooth Earth: without relief the camera
    // stays above ground wherever a test puts it.
    body_.terrain = nullptr;
    model_ = load_atmosphere(body_);
    atmosphere_ = shared::to_shared(model_);
  }

  // A renderer whose technique the test keeps a pointer to.
  HillaireTechnique* make_renderer(HillaireTechnique::Settings settings = {}) {
    renderer_ = std::make_unique<FrameRenderer>(kSize, kSize);
    auto technique = std::make_unique<HillaireTechnique>(settings);
    HillaireTechnique* raw = technique.get();
    renderer_->set_body(body_, model_, std::move(technique));
    return raw;
  }

  // Renders from a geodetic place looking along heading/pitch with the sun
  // at an elevation and azimuth seen from that place.
  std::vector<float> render(const Geodetic& place, double heading_deg, double pitch_deg,
                            double sun_elevation_deg, double sun_azimuth_deg,
                            double fov_deg = 90.0) {
    auto view = view_from_place(body_.shape, place, heading_deg, pitch_deg, fov_deg,
                                sun_elevation_deg, sun_azimuth_deg);
    renderer_->render(view.camera, view.sun_dir_body, 10.0);
    return renderer_->read_hdr();
  }

  static std::vector<float> read_texture(GLuint texture, int width, int height, int depth = 1) {
    std::vector<float> texels(size_t(width) * size_t(height) * size_t(depth) * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)),
                      texels.data());
    return texels;
  }

  static bool all_finite(const std::vector<float>& values) {
    for (float v : values) {
      if (!std::isfinite(v)) return false;
    }
    return true;
  }

  std::unique_ptr<GlContext> context_;
  Body body_;
  AtmosphereModel model_;
  shared::Atmosphere atmosphere_;
  std::unique_ptr<FrameRenderer> renderer_;
};

TEST_F(HillaireGLTest, TransmittanceLutMatchesCpuOpticalDepth) {
  HillaireTechnique* technique = make_renderer();
  render({glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 10.0, 30.0, 180.0);
  const int w = shared::kTransmittanceLutWidth, h = shared::kTransmittanceLutHeight;
  auto lut = read_texture(technique->transmittance_lut(), w, h);
  double worst = 0.0, worst_column = 0.0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double r, mu;
      shared::transmittance_lut_r_mu_from_uv(atmosphere_, (x + 0.5) / w, (y + 0.5) / h, r, mu);
      glm::dvec3 tau_cpu = shared::optical_depth_to_top(atmosphere_, r, mu, 40);
      for (int c = 0; c < 3; ++c) {
        double t_gpu = lut[(size_t(y) * w + size_t(x)) * 4 + size_t(c)];
        ASSERT_GT(t_gpu, 0.0) << "texel " << x << ", " << y;
        // Optical depth, not transmittance, is what float rounds: its
        // 41-term sum and the uv -> (r, mu) inversion in float leave a few
        // 1e-6 relative, plus the rounding of mu near the horizon, where
        // tau changes by ~1e-3 per 1e-6 of mu at the ground.
        double error = std::abs(-std::log(t_gpu) - tau_cpu[c]);
        double allowed = 2e-4 * tau_cpu[c] + 2e-6;
        worst = std::max(worst, error / allowed);
        ASSERT_LE(error, allowed) << "texel " << x << ", " << y << " channel " << c << " r " << r
                                  << " mu " << mu << " tau " << tau_cpu[c];
      }
      // Alpha: the Mie density's column (metres), the same sum. Mie's thin
      // layer makes it the more sensitive to mu's rounding at the horizon.
      double column_cpu = hillaire::mie_column_to_top(atmosphere_, r, mu, 40);
      double column_gpu = lut[(size_t(y) * w + size_t(x)) * 4 + 3];
      double column_allowed = 5e-4 * column_cpu + 1e-2;
      worst_column = std::max(worst_column, std::abs(column_gpu - column_cpu) / column_allowed);
      ASSERT_LE(std::abs(column_gpu - column_cpu), column_allowed)
          << "texel " << x << ", " << y << " r " << r << " mu " << mu;
    }
  }
  std::printf("transmittance LUT: worst error %.3f of the allowed, Mie column %.3f\n", worst,
              worst_column);
}

TEST_F(HillaireGLTest, ForwardGainLutMatchesCpuSeries) {
  HillaireTechnique* technique = make_renderer();
  render({glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 10.0, 30.0, 180.0);
  const int w = shared::kForwardGainLutWidth, h = shared::kForwardGainLutHeight;
  auto lut = read_texture(technique->forward_gain_lut(), w, h);
  double worst = 0.0, largest = 0.0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double nu, tau;
      hillaire::forward_gain_lut_nu_tau_from_uv((x + 0.5) / w, (y + 0.5) / h, nu, tau);
      double cpu = hillaire::forward_gain_times_extinction(model_.mie_g, 0.0, nu, tau);
      double gpu = lut[(size_t(y) * w + size_t(x)) * 4];
      // 62 terms summed in float, the largest near the peak's 0.4 per sr:
      // a few 1e-7 per sr.
      double error = std::abs(gpu - cpu);
      double allowed = 2e-5 * std::abs(cpu) + 2e-6;
      worst = std::max(worst, error / allowed);
      largest = std::max(largest, std::abs(cpu));
      ASSERT_LE(error, allowed) << "texel " << x << ", " << y << " nu " << nu << " tau " << tau;
    }
  }
  // A table of zeros would pass the comparison above with no gain at all.
  EXPECT_GT(largest, 0.1);
  std::printf("forward-gain LUT: worst error %.3f of the allowed, largest %.3f per sr\n", worst,
              largest);
}

TEST_F(HillaireGLTest, PaperMultipleScatteringLutMatchesCpuIntegral) {
  HillaireTechnique::Settings settings;
  settings.multiple_scattering = HillaireTechnique::MultipleScattering::kPaper;
  HillaireTechnique* technique = make_renderer(settings);
  render({glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 10.0, 30.0, 180.0);
  const int w = shared::kMultipleScatteringLutWidth, h = shared::kMultipleScatteringLutHeight;
  // The mean's part; the moments' parts stay zero with the paper's LUT.
  const int width = hillaire::kFieldParts * w;
  auto lut = read_texture(technique->multiple_scattering_lut(), width, h);
  for (size_t i = 0; i < lut.size(); i += 4) {
    if (int(i / 4) % width >= w) {
      ASSERT_EQ(lut[i], 0.0f);
    }
  }
  double worst = 0.0;
  // Every third texel in each direction, corners included: the CPU
  // integral in double takes ~10 ms a texel.
  for (int y = 0; y < h; y += 3) {
    for (int x = 0; x < w; x += 3) {
      double r, mu_s;
      hillaire::multiple_scattering_lut_r_mu_s_from_uv(atmosphere_, (x + 0.5) / w, (y + 0.5) / h, r,
                                                       mu_s);
      glm::dvec3 cpu = hillaire::multiple_scattering_texel(atmosphere_, r, mu_s);
      for (int c = 0; c < 3; ++c) {
        double gpu = lut[(size_t(y) * size_t(width) + size_t(x)) * 4 + size_t(c)];
        // The GPU reads the sun's transmittance from the bilinear LUT, the
        // CPU integrates it at the exact (r, mu): 0.2% covers the
        // interpolation, plus an absolute floor for the night side, where
        // the values fall to ~1e-4 and a sample near the shadow's edge can
        // fall on either side of it in float and in double (0.33 %, 1e-7,
        // at mu_s = -0.11, 58 km up).
        double allowed = 2e-3 * cpu[c] + 2e-7;
        double error = std::abs(gpu - cpu[c]);
        worst = std::max(worst, error / allowed);
        EXPECT_LE(error, allowed) << "texel " << x << ", " << y << " channel " << c << " r " << r
                                  << " mu_s " << mu_s << " cpu " << cpu[c];
      }
    }
  }
  std::printf("paper's multiple-scattering LUT: worst error %.3f of the allowed\n", worst);
}

// The orders of scattering: each GPU order (its moments and the ground's
// irradiance, on its own grid) against the CPU's integral of the same
// order from the GPU's previous one (read back, so that an error cannot
// hide by compounding), and the LUT against their sum.
TEST_F(HillaireGLTest, ScatteringOrdersMatchCpuIntegrals) {
  HillaireTechnique* technique = make_renderer();
  render({glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 10.0, 30.0, 180.0);
  const int w = shared::kMultipleScatteringLutWidth, h = shared::kMultipleScatteringLutHeight;
  const int width = hillaire::kFieldParts * w;
  // Some orders on the LUT's grid and some on a coarser one, or this test
  // checks one of the two alone.
  ASSERT_EQ(hillaire::scattering_order_width(1), w);
  ASSERT_LT(hillaire::scattering_order_width(hillaire::kScatteringOrders), w);
  struct Order {
    int w, h;
    std::vector<float> table;
    glm::dvec3 at(int x, int y) const {
      const float* t = &table[(size_t(y) * size_t(hillaire::kFieldParts * w) + size_t(x)) * 4];
      return glm::dvec3(t[0], t[1], t[2]);
    }
    // Part `part` at the LUT's texel (x, y) (y = h of the LUT: the ground's
    // row), bilinear between the order's own texels.
    glm::dvec3 at_lut_texel(int part, int x, int y, int lut_w, int lut_h) const {
      if (w == lut_w && h == lut_h) return at(x + part * w, y);
      double u = hillaire::regrid_texture_coord((x + 0.5) / lut_w, lut_w, w);
      double px = std::clamp(u * w - 0.5, 0.0, double(w - 1));
      double py = h;
      if (y < lut_h) {
        double v = hillaire::regrid_texture_coord((y + 0.5) / lut_h, lut_h, h);
        py = std::clamp(v * h - 0.5, 0.0, double(h - 1));
      }
      int x0 = int(px), y0 = int(py);
      int x1 = std::min(x0 + 1, w - 1), y1 = y < lut_h ? std::min(y0 + 1, h - 1) : y0;
      double fx = px - x0, fy = py - y0;
      return glm::mix(glm::mix(at(part * w + x0, y0), at(part * w + x1, y0), fx),
                      glm::mix(at(part * w + x0, y1), at(part * w + x1, y1), fx), fy);
    }
  };
  std::vector<Order> orders;
  for (int k = 1; k <= hillaire::kScatteringOrders; ++k) {
    const int ow = hillaire::scattering_order_width(k), oh = hillaire::scattering_order_height(k);
    orders.push_back(
        {ow, oh,
         read_texture(technique->scattering_order_lut(k), hillaire::kFieldParts * ow, oh + 1)});
  }
  // Same allowance as the paper's LUT (bilinear transmittance, and here
  // the previous order, on the GPU against exact values on the CPU), on
  // the scale of the mean for the other terms, which can pass through zero.
  double worst = 0.0;
  auto check = [&](const glm::dvec3& cpu, const glm::dvec3& gpu, const glm::dvec3& scale,
                   const char* what, int k, int x, int y) {
    for (int c = 0; c < 3; ++c) {
      double allowed = 2e-3 * std::abs(scale[c]) + 2e-7;
      worst = std::max(worst, std::abs(gpu[c] - cpu[c]) / allowed);
      EXPECT_NEAR(gpu[c], cpu[c], allowed)
          << what << " of order " << k << " at texel " << x << ", " << y << " channel " << c;
    }
  };
  for (int k = 1; k <= hillaire::kScatteringOrders; ++k) {
    const Order& gpu = orders[size_t(k - 1)];
    const float* previous = k > 1 ? orders[size_t(k - 2)].table.data() : nullptr;
    // The texel's centre on the LUT's grid, whose mapping the order shares.
    auto lut_coord = [](int i, int from, int to) {
      return hillaire::regrid_texture_coord((i + 0.5) / from, from, to);
    };
    for (int x = 0; x < gpu.w; x += gpu.w == w ? 9 : 3) {
      double r, mu_s;
      hillaire::multiple_scattering_lut_r_mu_s_from_uv(atmosphere_, lut_coord(x, gpu.w, w), 0.5 / h,
                                                       r, mu_s);
      glm::dvec3 e =
          hillaire::gather_order_from(previous, k, atmosphere_,
                                      hillaire::ground_gather_radius(atmosphere_), mu_s, true)
              .part[hillaire::kFieldMean];
      check(e, gpu.at(x, gpu.h), e, "E", k, x, gpu.h);
      for (int y = 0; y < gpu.h; y += 5) {
        hillaire::multiple_scattering_lut_r_mu_s_from_uv(atmosphere_, lut_coord(x, gpu.w, w),
                                                         lut_coord(y, gpu.h, h), r, mu_s);
        hillaire::FieldMoments f =
            hillaire::gather_order_from(previous, k, atmosphere_, r, mu_s, false);
        for (int part = 0; part < hillaire::kFieldParts; ++part) {
          check(hillaire::field_part(f, part), gpu.at(x + part * gpu.w, y),
                f.part[hillaire::kFieldMean], "part", k, x, y);
        }
      }
    }
  }
  std::printf("scattering orders: worst error %.3f of the allowed\n", worst);
  // The LUT is the sum with its tail, texel for texel, each order read
  // between its own texels where its grid is coarser.
  auto lut = read_texture(technique->multiple_scattering_lut(), width, h);
  auto ground = read_texture(technique->ground_irradiance_lut(), w, 1);
  auto sum_at = [&](int part, int x, int y) {
    glm::dvec3 all(0.0);
    for (const Order& order : orders) all += order.at_lut_texel(part, x, y, w, h);
    const size_t last = orders.size() - 1;
    return hillaire::with_geometric_tail(
        orders[last - 1].at_lut_texel(hillaire::kFieldMean, x, y, w, h),
        orders[last].at_lut_texel(hillaire::kFieldMean, x, y, w, h), all,
        orders[last].at_lut_texel(part, x, y, w, h));
  };
  // In float on the GPU: on the scale of the mean, as above.
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y <= h; ++y) {
      const glm::dvec3 mean = sum_at(hillaire::kFieldMean, x, y);
      for (int part = 0; part < (y < h ? hillaire::kFieldParts : 1); ++part) {
        glm::dvec3 sum = sum_at(part, x, y);
        const float* t = y < h ? &lut[(size_t(y) * size_t(width) + size_t(part * w + x)) * 4]
                               : &ground[size_t(x) * 4];
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(t[c], sum[c], 1e-5 * std::abs(mean[c]) + 1e-12)
              << "part " << part << " at texel " << x << ", " << y;
        }
      }
    }
  }
  // Later orders are weaker at the sunlit ground: the series converges.
  for (int c = 0; c < 3; ++c) {
    for (size_t k = 1; k < orders.size(); ++k) {
      EXPECT_GT(orders[k - 1].at_lut_texel(hillaire::kFieldMean, w - 1, 0, w, h)[c],
                orders[k].at_lut_texel(hillaire::kFieldMean, w - 1, 0, w, h)[c]);
    }
  }
}

TEST_F(HillaireGLTest, NoNanOrInfFromTheGroundToDeepSpaceAndInsideThePlanet) {
  HillaireTechnique* technique = make_renderer();
  struct View {
    const char* what;
    Geodetic place;
    double pitch_deg;
  };
  const View views[] = {
      {"1 m", {glm::radians(46.5), glm::radians(8.0), 1.0}, 5.0},
      {"100 km", {glm::radians(46.5), glm::radians(8.0), 100e3}, -20.0},
      {"1e6 km", {glm::radians(46.5), glm::radians(8.0), 1e9}, -90.0},
      {"inside the planet", {glm::radians(46.5), glm::radians(8.0), -2000.0}, 5.0},
  };
  for (const View& view : views) {
    for (double sun_elevation : {60.0, 2.0, -5.0, -90.0}) {
      SCOPED_TRACE(::testing::Message() << view.what << ", sun at " << sun_elevation << " deg");
      auto hdr = render(view.place, 0.0, view.pitch_deg, sun_elevation, 90.0);
      EXPECT_TRUE(all_finite(hdr)) << "image";
      EXPECT_TRUE(
          all_finite(read_texture(technique->transmittance_lut(), shared::kTransmittanceLutWidth,
                                  shared::kTransmittanceLutHeight)))
          << "transmittance LUT";
      EXPECT_TRUE(
          all_finite(read_texture(technique->multiple_scattering_lut(),
                                  hillaire::kFieldParts * shared::kMultipleScatteringLutWidth,
                                  shared::kMultipleScatteringLutHeight)))
          << "multiple-scattering LUT";
      for (int k = 1; k <= hillaire::kScatteringOrders; ++k) {
        EXPECT_TRUE(
            all_finite(read_texture(technique->scattering_order_lut(k),
                                    hillaire::kFieldParts * hillaire::scattering_order_width(k),
                                    hillaire::scattering_order_height(k) + 1)))
            << "order " << k;
      }
      EXPECT_TRUE(all_finite(
          read_texture(technique->ground_irradiance_lut(), shared::kMultipleScatteringLutWidth, 1)))
          << "ground's sky irradiance";
      if (technique->lut_weight() > 0.0) {
        EXPECT_TRUE(all_finite(read_texture(technique->sky_view_lut(), shared::kSkyViewLutWidth,
                                            shared::kSkyViewLutHeight)))
            << "sky-view LUT";
        const int a = shared::kAerialPerspectiveSize;
        EXPECT_TRUE(all_finite(read_texture(technique->aerial_scattering(), a, a, a)))
            << "aerial scattering";
        EXPECT_TRUE(all_finite(read_texture(technique->aerial_transmittance(), a, a, a)))
            << "aerial transmittance";
      }
    }
  }
}

// The planet's shadow: with the sun 30 degrees below the horizon of the
// point below, the night side seen from 400 km is dark, air and ground.
// On Mars's northern lowlands the camera stands below the bottom sphere,
// and the sky pass lifts it onto it. A ray that clears the terrain's
// horizon must see the sky beyond, not the lifted sphere's ground just
// below its horizon: that drew a band along the horizon, 4x darker in red
// than both the sky above and the terrain below (red 0.005 against 0.017
// at the darkest elsewhere). The view is data/flights/terrain_mars.json's
// first frame over the procedural Mars, 2 m above the ground and 748 m
// below the reference surface.
TEST(HillaireLowlandsGLTest, NoDarkBandWhereTheTerrainLiesBelowTheBottomSphere) {
  setenv("PLANET_GL_DEBUG", "1", 1);
  auto context = GlContext::create_headless();
  // The procedural Mars, whose lowland this view was found over.
  Body body = load_body(project_root() / "tests/data/planets/mars_procedural.json");
  AtmosphereModel model = load_atmosphere(body);
  const int width = 240, height = 135;
  FrameRenderer renderer(width, height);
  renderer.set_body(body, model, std::make_unique<HillaireTechnique>());
  auto view = view_from_place(body.shape, {glm::radians(18.65), glm::radians(-134.8), -747.912},
                              200.0, 4.0, 60.0, 30.0, 120.0);
  renderer.render(view.camera, view.sun_dir_body, 6.0);
  std::vector<float> hdr = renderer.read_hdr();
  float darkest = 1e30f;
  int at = 0;
  for (int i = 0; i < width * height; ++i) {
    if (hdr[size_t(i) * 4] < darkest) {
      darkest = hdr[size_t(i) * 4];
      at = i;
    }
  }
  EXPECT_GT(darkest, 0.012f) << "pixel " << at % width << ", " << at / width << " (rows bottom-up)";
}

TEST_F(HillaireGLTest, NightSideIsDarkFromOrbit) {
  make_renderer();
  auto hdr = render({0.0, 0.0, 400e3}, 90.0, -60.0, -30.0, 90.0, 40.0);
  size_t centre = (size_t(kSize / 2) * kSize + kSize / 2) * 4;
  double night = 0.2126 * hdr[centre] + 0.7152 * hdr[centre + 1] + 0.0722 * hdr[centre + 2];
  // Sunlit ground from orbit is ~1e-2 in these units; the shadowed
  // atmosphere has only light scattered in from the far terminator.
  EXPECT_LT(night, 1e-5);
  EXPECT_TRUE(all_finite(hdr));
}

// Frames of a climb from 40 to 96 km through the altitudes where the
// per-pixel path takes over (60 to 80 km). A pop shows as a frame far from
// the mean of its neighbours: the RMS of f_i - (f_(i-1) + f_(i+1)) / 2 over
// the pixels, relative to the frame's mean, must stay within what either
// path alone gives at the same frame.
TEST_F(HillaireGLTest, SwitchToPerPixelMarchingDoesNotPop) {
  constexpr int kFrames = 29;
  auto climb = [&](HillaireTechnique::Path path, double switch_width = 0.2) {
    HillaireTechnique::Settings settings;
    settings.path = path;
    settings.switch_end = settings.switch_start + switch_width;
    make_renderer(settings);
    std::vector<std::vector<float>> frames;
    for (int i = 0; i < kFrames; ++i) {
      double height = 40e3 + 2e3 * i;
      frames.push_back(
          render({glm::radians(46.5), glm::radians(8.0), height}, 0.0, -10.0, 30.0, 120.0));
    }
    return frames;
  };
  auto second_difference = [](const std::vector<std::vector<float>>& f, int i) {
    double sum_sq = 0, sum = 0;
    for (size_t k = 0; k < f[size_t(i)].size(); k += 4) {
      for (size_t c = 0; c < 3; ++c) {
        double mean = 0.5 * (f[size_t(i - 1)][k + c] + f[size_t(i + 1)][k + c]);
        double d = f[size_t(i)][k + c] - mean;
        sum_sq += d * d;
        sum += f[size_t(i)][k + c];
      }
    }
    double n = double(f[size_t(i)].size() / 4 * 3);
    return std::sqrt(sum_sq / n) / (sum / n);
  };
  auto by_altitude = climb(HillaireTechnique::Path::kByAltitude);
  auto luts = climb(HillaireTechnique::Path::kLuts);
  auto per_pixel = climb(HillaireTechnique::Path::kPerPixel);
  double worst_ratio = 0, worst_switch = 0, worst_alone = 0;
  for (int i = 1; i + 1 < kFrames; ++i) {
    double d_switch = second_difference(by_altitude, i);
    double d_alone = std::max(second_difference(luts, i), second_difference(per_pixel, i));
    worst_switch = std::max(worst_switch, d_switch);
    worst_alone = std::max(worst_alone, d_alone);
    worst_ratio = std::max(worst_ratio, d_switch / d_alone);
    // 10% over the worse path alone: the blend's own curvature in altitude
    // may add a little, a pop adds its whole jump.
    EXPECT_LE(d_switch, 1.1 * d_alone) << "frame " << i << " at " << 40 + 2 * i << " km";
  }
  std::printf(
      "switch: worst second difference %.5f with the switch, %.5f with one path alone, "
      "worst ratio %.3f\n",
      worst_switch, worst_alone, worst_ratio);
  // The measure must see a pop where there is one: a switch within 10 m.
  auto hard = climb(HillaireTechnique::Path::kByAltitude, 1e-4);
  double worst_hard_ratio = 0;
  for (int i = 1; i + 1 < kFrames; ++i) {
    double d_alone = std::max(second_difference(luts, i), second_difference(per_pixel, i));
    worst_hard_ratio = std::max(worst_hard_ratio, second_difference(hard, i) / d_alone);
  }
  std::printf("switch within 10 m: worst ratio %.3f\n", worst_hard_ratio);
  EXPECT_GT(worst_hard_ratio, 1.3) << "a hard switch must show as a pop";
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
