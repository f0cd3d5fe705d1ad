// The detail below the elevation grids (terrain/grid_detail.h): it
// averages to zero over each of the grid's cells and is zero at every
// sample, its roughness follows the relief, coasts stay coasts, it is
// seamless across the date line and at the poles, the same on every
// thread, and its bounds hold.
#include "terrain/grid_detail.h"
#include "terrain/craters.h"
#include "terrain/noise.h"
#include "terrain/terrain_config.h"

#include "core/data_paths.h"
#include "core/error.h"
#include "sim/body.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kPi = glm::pi<double>();

struct Loaded {
  Body body;
  TerrainConfig config;
  const GridDetail* detail = nullptr;
};

// A shipped body, with its detail's spec changed by `edit` (none: as shipped).
Loaded load(const std::string& name, void (*edit)(nlohmann::json&) = nullptr) {
  Loaded l;
  l.body = load_body(find_body_file(name));
  if (edit) edit(l.body.terrain["height"]["detail"]);
  l.config = parse_terrain(l.body);
  l.detail = dynamic_cast<const GridDetail*>(l.config.heights.get());
  return l;
}

glm::dvec3 planetocentric(double lat, double lon) {
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// The direction at grid coordinates (u, v): the inverse of
// GridHeight::grid_coordinates (geodetic rows through the ellipsoid's ratio).
glm::dvec3 direction_at(const Loaded& l, double u, double v) {
  const GridSpec& s = l.detail->data().spec();
  double centre = s.registration == GridSpec::Registration::kPixel ? 0.5 : 0.0;
  double lon = glm::radians(s.west_longitude_deg) + (u + centre) * 2.0 * kPi / s.width;
  double lat = l.detail->row_latitude(v);
  if (s.geodetic_latitude) {
    double b = l.body.shape.polar_radius(), a = l.body.shape.equatorial_radius;
    lat = std::atan(std::tan(lat) * (b * b) / (a * a));
  }
  return planetocentric(lat, lon);
}

// Whole-number coordinates of the sample nearest a place.
void nearest_node(const Loaded& l, double lat_deg, double lon_deg, int& i, int& j) {
  double u, v;
  l.detail->grid_coordinates(planetocentric(glm::radians(lat_deg), glm::radians(lon_deg)), u, v);
  i = int(std::lround(u));
  j = int(std::lround(v));
}

TEST(GridDetailTest, EdgeNoiseStaysWithinItsBounds) {
  // The detail's height and error bounds rest on these three constants.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-40.0, 40.0);
  const double h = 1e-4;
  double max_value = 0, max_slope = 0, max_curvature = 0;
  for (int k = 0; k < 40000; ++k) {
    double x = u(rng), y = u(rng);
    for (int axis = 0; axis < 2; ++axis) {
      for (int64_t m : {2, 8}) {
        auto at = [&](double dx, double dy) {
          return edge_noise(x + dx, y + dy, axis, m, m / 2, 1 << 20, 9u);
        };
        EdgeNoise n = at(0, 0);
        max_value = std::max(max_value, std::abs(n.value));
        max_slope = std::max(max_slope, std::abs(n.slope));
        // The other first derivative, and the second ones, by differences.
        double across = axis == 0 ? (at(0, h).value - at(0, -h).value) / (2 * h)
                                  : (at(h, 0).value - at(-h, 0).value) / (2 * h);
        max_slope = std::max(max_slope, std::abs(across));
        double along = axis == 0 ? (at(h, 0).slope - at(-h, 0).slope) / (2 * h)
                                 : (at(0, h).slope - at(0, -h).slope) / (2 * h);
        double mixed = axis == 0 ? (at(0, h).slope - at(0, -h).slope) / (2 * h)
                                 : (at(h, 0).slope - at(-h, 0).slope) / (2 * h);
        max_curvature = std::max({max_curvature, std::abs(along), std::abs(mixed)});
      }
    }
  }
  // The divergence F_x + G_y of a pair (the detail's octave), and its slopes.
  double max_div = 0, max_div_slope = 0;
  for (int k = 0; k < 40000; ++k) {
    double x = u(rng), y = u(rng);
    auto div = [&](double dx, double dy) {
      return edge_noise(x + dx, y + dy, 0, 4, 2, 1 << 20, 3u).slope +
             edge_noise(x + dx, y + dy, 1, 4, 2, 1 << 20, 4u).slope;
    };
    max_div = std::max(max_div, std::abs(div(0, 0)));
    max_div_slope = std::max({max_div_slope, std::abs(div(h, 0) - div(-h, 0)) / (2 * h),
                              std::abs(div(0, h) - div(0, -h)) / (2 * h)});
  }
  std::printf(
      "edge noise: largest value %.3f, slope %.3f, curvature %.3f; divergence %.3f, "
      "its slope %.3f\n",
      max_value, max_slope, max_curvature, max_div, max_div_slope);
  EXPECT_LT(max_value, kEdgeNoiseMax);
  EXPECT_LT(max_slope, kEdgeNoiseMaxSlope);
  EXPECT_LT(max_curvature, kEdgeNoiseMaxCurvature);
  EXPECT_LT(max_div, kEdgeDivergenceMax);
  EXPECT_LT(max_div_slope, kEdgeDivergenceMaxSlope);
}

TEST(GridDetailTest, ZeroVolumeCraterHoldsNoVolume) {
  // The integral of x p(x) over the crater's reach (Simpson's rule): what
  // the bowl digs out, the rim and blanket hold.
  const int n = 20000;
  const double h = craters::kReach / n;
  double volume = 0, bowl = 0;
  for (int k = 0; k <= n; ++k) {
    double x = k * h, w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    double p = craters::zero_volume_profile(x);
    volume += w * x * p;
    bowl += w * x * std::min(p, 0.0);
  }
  volume *= h / 3.0;
  bowl *= h / 3.0;
  EXPECT_LT(std::abs(volume), 1e-5 * std::abs(bowl)) << volume << " against a bowl of " << bowl;
  EXPECT_NEAR(craters::zero_volume_profile(0.0), -1.7321, 1e-3);
}

// The mean of the detail over the grid cell whose sample is (i, j), by
// the midpoint rule on n x n points, weighted by area (cos latitude), and
// the largest |detail| seen.
struct CellMean {
  double mean = 0, peak = 0;
};
CellMean cell_mean(const Loaded& l, int i, int j, int n) {
  const double o = l.detail->edge_offset();
  // The cell: the pixel about the sample, or the square east and south of the node.
  const double u0 = o > 0 ? i - 0.5 : i, v0 = o > 0 ? j - 0.5 : j;
  double sum = 0, weight = 0;
  CellMean c;
  for (int b = 0; b < n; ++b) {
    for (int a = 0; a < n; ++a) {
      double u = u0 + (a + 0.5) / n, v = v0 + (b + 0.5) / n;
      double d = l.detail->detail(direction_at(l, u, v));
      double w = std::cos(l.detail->row_latitude(v));
      sum += w * d;
      weight += w;
      c.peak = std::max(c.peak, std::abs(d));
    }
  }
  c.mean = sum / weight;
  return c;
}

TEST(GridDetailTest, AveragesToZeroOverEachGridCell) {
  // Over cells of the Alps (Earth's node cells), Gale crater (Mars's
  // pixels, with craters) and Tycho (the Moon's): the mean against the
  // detail's size there. Three octaves of noise and two of craters, so
  // that 160 x 160 points resolve every feature (the construction is the
  // same at every octave). What is left: the midpoint rule's error, and
  // the noise's exact zero in grid units against this mean by area, whose
  // weight changes by tan(latitude) times a cell's 0.1 to 0.3 degrees.
  auto coarse = [](nlohmann::json& d) {
    d["octaves"] = 3;
    if (d.contains("craters")) d["craters"]["octaves"] = 2;
  };
  struct Where {
    const char* body;
    double lat, lon;
  };
  for (Where w :
       {Where{"earth", 46.55, 7.98}, Where{"mars", -5.4, 137.8}, Where{"moon", -43.31, -11.36}}) {
    Loaded l = load(w.body, coarse);
    ASSERT_TRUE(l.detail) << w.body << " has no detail";
    int i0, j0;
    nearest_node(l, w.lat, w.lon, i0, j0);
    double worst = 0;
    for (int j = j0 - 1; j <= j0 + 1; ++j) {
      for (int i = i0 - 1; i <= i0 + 1; ++i) {
        CellMean c = cell_mean(l, i, j, 160);
        ASSERT_GT(c.peak, 1.0) << w.body << ": no detail in cell " << i << ", " << j;
        worst = std::max(worst, std::abs(c.mean) / c.peak);
        EXPECT_LT(std::abs(c.mean), 2e-4 * c.peak)
            << w.body << " cell " << i << ", " << j << ": mean " << c.mean << " m, peak " << c.peak
            << " m";
      }
    }
    std::printf("%s: the largest cell mean is %.2e of the cell's largest detail\n", w.body, worst);
  }
}

TEST(GridDetailTest, SamplesKeepTheGridsValues) {
  // At every sample of a patch, the surface with its detail is the
  // grid's sample (with every octave and crater the body ships).
  struct Where {
    const char* body;
    double lat, lon;
  };
  for (Where w :
       {Where{"earth", 46.55, 7.98}, Where{"mars", -5.4, 137.8}, Where{"moon", -43.31, -11.36}}) {
    Loaded l = load(w.body);
    ASSERT_TRUE(l.detail) << w.body;
    int i0, j0;
    nearest_node(l, w.lat, w.lon, i0, j0);
    double worst = 0, typical = 0;
    for (int j = j0 - 6; j <= j0 + 6; ++j) {
      for (int i = i0 - 6; i <= i0 + 6; ++i) {
        glm::dvec3 dir = direction_at(l, i, j);
        double off = std::abs(l.detail->seabed_height(dir) - l.detail->data().sample(i, j));
        worst = std::max(worst, off);
        // Between samples, for scale.
        typical =
            std::max(typical, std::abs(l.detail->detail(direction_at(l, i + 0.37, j + 0.61))));
      }
    }
    std::printf(
        "%s: at 169 samples the surface is within %.2e m of the grid (detail between "
        "them up to %.0f m)\n",
        w.body, worst, typical);
    EXPECT_LT(worst, 1e-3) << w.body;
    EXPECT_GT(typical, 1.0) << w.body;
  }
}

TEST(GridDetailTest, RoughnessFollowsTheRelief) {
  // The detail's spread over a patch of 10 x 10 cells: ranges, plains and
  // the sea floor.
  Loaded earth = load("earth");
  ASSERT_TRUE(earth.detail);
  auto spread = [&](double lat, double lon) {
    int i0, j0;
    nearest_node(earth, lat, lon, i0, j0);
    double sum = 0;
    int n = 0;
    for (int k = 0; k < 400; ++k) {
      double u = i0 + 10.0 * (k % 20) / 20.0 + 0.013, v = j0 + 10.0 * (k / 20) / 20.0 + 0.029;
      double d = earth.detail->detail(direction_at(earth, u, v));
      sum += d * d;
      ++n;
    }
    return std::sqrt(sum / n);
  };
  double alps = spread(46.4, 7.6), himalaya = spread(28.0, 86.5);
  double plains = spread(38.5, -99.0), sea_floor = spread(10.0, -140.0);
  std::printf("detail rms: Alps %.0f m, Himalaya %.0f m, Kansas %.1f m, Pacific floor %.1f m\n",
              alps, himalaya, plains, sea_floor);
  EXPECT_GT(alps, 100.0);
  EXPECT_GT(himalaya, 100.0);
  EXPECT_LT(plains, 0.2 * alps);
  EXPECT_LT(sea_floor, plains);
}

TEST(GridDetailTest, CoastsStayCoasts) {
  // Points near Earth's coasts (the grid within 300 m of the sea's level):
  // land stays above the sea and the floor below it.
  Loaded earth = load("earth");
  ASSERT_TRUE(earth.detail);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int coastal = 0, moved = 0;
  while (coastal < 3000) {
    glm::dvec3 dir = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    double grid = static_cast<const GridHeight&>(*earth.detail).GridHeight::seabed_height(dir);
    if (std::abs(grid) > 300.0) continue;
    ++coastal;
    double with = earth.detail->seabed_height(dir);
    if (grid > 0) {
      EXPECT_GT(with, 0.0) << "land sank below the sea";
    } else if (grid < 0) {
      EXPECT_LT(with, 0.0) << "sea floor rose above the sea";
    }
    moved += with != grid;
  }
  std::printf("coasts: %d points within 300 m of the sea's level, %d of them moved by the detail\n",
              coastal, moved);
  EXPECT_GT(moved, coastal / 2) << "the coasts lost their detail";
}

TEST(GridDetailTest, SeamlessAcrossTheDateLineTheGridsEdgeAndThePoles) {
  for (const char* name : {"earth", "mars", "moon"}) {
    Loaded l = load(name);
    ASSERT_TRUE(l.detail) << name;
    const double e = 1e-10;  // radians: well under a millimetre
    for (double lat_deg : {-60.0, -12.3, 0.0, 33.3, 65.0}) {
      double lat = glm::radians(lat_deg);
      for (double lon : {kPi, 0.0}) {
        double west = l.detail->height(planetocentric(lat, lon - e));
        double east = l.detail->height(planetocentric(lat, lon + e));
        EXPECT_NEAR(west, east, 1e-3) << name << " at " << lat_deg << ", " << lon;
      }
    }
    // Near each pole, every meridian meets the pole's one value.
    for (double sign : {1.0, -1.0}) {
      double pole = l.detail->height(glm::dvec3(0, 0, sign));
      for (double lon_deg : {-179.9, -90.0, 0.0, 45.0, 179.9}) {
        double near = l.detail->height(
            planetocentric(sign * glm::radians(90.0 - 1e-6), glm::radians(lon_deg)));
        EXPECT_NEAR(near, pole, 1.0) << name << " pole " << sign << " lon " << lon_deg;
      }
    }
    // And continuous anywhere: two points a millimetre apart.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
      glm::dvec3 a = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
      glm::dvec3 b = glm::normalize(a + 1e-3 / l.body.shape.equatorial_radius *
                                            glm::dvec3(unit(rng), unit(rng), unit(rng)));
      EXPECT_NEAR(l.detail->height(a), l.detail->height(b), 0.05) << name;
    }
  }
}

TEST(GridDetailTest, SameHeightsOnEveryThread) {
  Loaded mars = load("mars");
  ASSERT_TRUE(mars.detail);
  std::vector<glm::dvec3> dirs;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 4000; ++k)
    dirs.push_back(glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng))));
  std::vector<double> serial, a(dirs.size()), b(dirs.size());
  for (const auto& d : dirs) serial.push_back(mars.detail->height(d));
  std::thread ta([&] {
    for (size_t k = 0; k < dirs.size(); ++k) a[k] = mars.detail->height(dirs[k]);
  });
  std::thread tb([&] {
    for (size_t k = dirs.size(); k-- > 0;) b[k] = mars.detail->height(dirs[k]);
  });
  ta.join();
  tb.join();
  EXPECT_EQ(a, serial);
  EXPECT_EQ(b, serial);
}

TEST(GridDetailTest, RangeNearAndInterpolationErrorHold) {
  for (const char* name : {"earth", "mars", "moon"}) {
    Loaded l = load(name);
    ASSERT_TRUE(l.detail) << name;
    const double R = l.body.shape.equatorial_radius;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int n = 0; n < 150; ++n) {
      glm::dvec3 c = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
      double radius = std::pow(10.0, 2.0 + 4.0 * (n % 10) / 9.0);  // 100 m to 1000 km
      HeightRange r = l.detail->range_near(c, radius);
      for (int k = 0; k < 40; ++k) {
        glm::dvec3 axis =
            glm::normalize(glm::cross(c, glm::dvec3(unit(rng), unit(rng), unit(rng))));
        double a = std::abs(unit(rng)) * radius / R;
        glm::dvec3 p = c * std::cos(a) + glm::cross(axis, c) * std::sin(a);
        double h = l.detail->height(p);
        EXPECT_GE(h, r.min - 1e-6) << name << " radius " << radius;
        EXPECT_LE(h, r.max + 1e-6) << name << " radius " << radius;
      }
    }
    for (double spacing : {0.5, 5.0, 60.0, 257.0, 1e3, 3e4}) {
      double bound = l.detail->interpolation_error(spacing), worst = 0;
      for (int n = 0; n < 400; ++n) {
        glm::dvec3 a = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        glm::dvec3 axis =
            glm::normalize(glm::cross(a, glm::dvec3(unit(rng), unit(rng), unit(rng))));
        double t = spacing / R;
        glm::dvec3 b = a * std::cos(t) + glm::cross(axis, a) * std::sin(t);
        glm::dvec3 m = glm::normalize(a + b);
        double off =
            std::abs(l.detail->height(m) - 0.5 * (l.detail->height(a) + l.detail->height(b)));
        worst = std::max(worst, off);
      }
      EXPECT_LE(worst, bound) << name << " spacing " << spacing;
      std::printf(
          "%s: spacing %g m, largest chord error %.3g m, bound %.3g m (the grid's own %.3g m)\n",
          name, spacing, worst, bound,
          static_cast<const GridHeight&>(*l.detail).GridHeight::interpolation_error(spacing));
    }
  }
}

TEST(GridDetailTest, BodyFileDetailIsCheckedNamingTheField) {
  auto refused = [](void (*edit)(nlohmann::json&), const std::string& says) {
    try {
      load("mars", edit);
      FAIL() << "accepted; expected: " << says;
    } catch (const InputError& e) {
      std::string m = e.what();
      EXPECT_NE(m.find("mars.json"), std::string::npos) << m;
      EXPECT_NE(m.find(says), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  };
  refused([](nlohmann::json& d) { d["gain_rough"] = 1.5; }, "gain_rough");
  refused([](nlohmann::json& d) { d["octaves"] = -1; }, "octaves");
  refused([](nlohmann::json& d) { d["craters"]["sfd_exponent"] = 9; }, "sfd_exponent");
  refused([](nlohmann::json& d) { d["roughness"] = 1; }, "roughness");
  refused([](nlohmann::json& d) { d["max_amplitude_m"] = 0.5; }, "max_amplitude_m");
  // Without a "detail", the grid's interpolation alone.
  Body mars = load_body(find_body_file("mars"));
  mars.terrain["height"].erase("detail");
  EXPECT_EQ(dynamic_cast<const GridDetail*>(parse_terrain(mars).heights.get()), nullptr);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
