#include "lab/clarity.h"

#include "atmosphere/math/shared_math.h"
#include "atmosphere/reference/columns.h"
#include "atmosphere/reference/sampling.h"
#include "core/error.h"
#include "core/parallel.h"

#include <fmt/format.h>

#include <cmath>
#include <memory>

namespace planet {

namespace {

constexpr int kViewWidth = 8, kViewHeight = 64;

Scene clarity_view(std::string name, std::string description, std::string body,
                   const ScenePlacement& placement) {
  Scene s;
  s.name = std::move(name);
  s.description = std::move(description);
  s.body = std::move(body);
  s.width = kViewWidth;
  s.height = kViewHeight;
  return placed(std::move(s), placement);
}

// The row's central ray (ndc x = 0), as ReferenceView::ray_dir has it.
glm::dvec3 row_ray(const ReferenceView& view, int y) {
  double ndc_y = 1.0 - 2.0 * (y + 0.5) / view.height;
  return glm::normalize(view.ray_from_ndc * glm::dvec3(0.0, ndc_y, 1.0));
}

// The model's optical depth along o + t d for t in [t0, t1], per channel,
// by the midpoint rule at steps short against the aerosols' scale height
// along the ray's fall.
glm::dvec3 optical_depth(const shared::Atmosphere& atmosphere, const glm::dvec3& o,
                         const glm::dvec3& d, double t0, double t1) {
  constexpr int kSteps = 20000;
  const double dt = (t1 - t0) / kSteps;
  glm::dvec3 tau(0.0);
  for (int i = 0; i < kSteps; ++i) {
    glm::dvec3 p = o + (t0 + (i + 0.5) * dt) * d;
    tau += shared::extinction_at(atmosphere, glm::length(p) - atmosphere.bottom_radius) * dt;
  }
  return tau;
}

}  // namespace

std::vector<Scene> clarity_views() {
  // The ascent flight's place, heading and sun (data/flights/ascent.json):
  // east over the Bernese Alps, the sun 25 deg up in the south-east. The
  // ground is the smooth bottom sphere, so the place sets the sun alone.
  // A 60 deg field pitched 30 deg down runs from the horizontal to 60 deg
  // below it: the horizon's sky in the top rows (the horizon is 2.5 deg
  // down from 6 km, 4.4 deg from 10 km over Mars), the ground from 7 km away
  // out to the horizon below. From 400 km the limb is 19.7 deg down: 18 to
  // 90 deg.
  ScenePlacement earth{46.55, 8.0, 6000.0, 90.0, -30.0, 60.0, 25.0, 140.0};
  ScenePlacement orbit = earth;
  orbit.height_m = 400e3;
  orbit.pitch_deg = -54.0;
  orbit.vertical_fov_deg = 72.0;
  ScenePlacement mars = earth;
  mars.lat_deg = 20.0;
  mars.height_m = 10e3;
  return {
      clarity_view("earth_6km", "6 km over Earth, east toward the horizon", "earth", earth),
      clarity_view("earth_400km", "400 km over Earth, from the nadir to the limb", "earth", orbit),
      clarity_view("mars_10km", "10 km over Mars, east toward the horizon", "mars", mars),
  };
}

Scene find_clarity_view(const std::string& name) {
  std::string known;
  for (const Scene& s : clarity_views()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw InputError(fmt::format("'{}' is not a clarity view ({})", name, known));
}

Scene clarity_scene(const Scene& view, double albedo, bool uniform) {
  Scene s = view;
  s.target_albedo = albedo;
  if (uniform) s.ground_albedo = albedo;
  return s;
}

PathBudget clarity_reference_paths() { return PathBudget(4096); }

std::vector<ClarityRow> clarity_rows(const Scene& view, int paths, bool uniform) {
  const Body body = scene_body(view);
  const AtmosphereModel model = scene_atmosphere(view, body);
  const ReferenceView ref = reference_view(view, body, model);
  const shared::Atmosphere atmosphere = shared::to_shared(model);
  const glm::dvec3 up = glm::normalize(ref.camera_atmo);
  std::vector<ClarityRow> rows(size_t(view.height));
  for (int y = 0; y < view.height; ++y) {
    ClarityRow& row = rows[size_t(y)];
    row.row = y;
    glm::dvec3 d = row_ray(ref, y);
    row.depression_deg = glm::degrees(-std::asin(glm::dot(d, up)));
    double t0 = 0, t1 = 0;
    if (!shared::ray_shell(ref.camera_atmo, d, model.bottom_radius, model.top_radius, t0, t1)) {
      continue;
    }
    double near = 0, far = 0;
    row.ground =
        shared::ray_sphere(ref.camera_atmo, d, model.bottom_radius, near, far) && near > 0.0;
    if (!row.ground) continue;
    row.range_m = near;
    row.tau = optical_depth(atmosphere, ref.camera_atmo, d, t0, t1);
  }
  if (paths <= 0) return rows;
  // The ground's own radiance L0 where each ray meets it, seen from 1 m
  // before it along the ray: each ground, each channel, `paths` paths with
  // the same numbers over both grounds (their difference is then less
  // noisy than either).
  // One table of columns serves both: the grounds' media differ in their
  // channels' albedo alone, which the depth tables carry.
  Medium media[2];
  TraceOptions trace[2];
  for (int g = 0; g < 2; ++g) {
    Scene s = clarity_scene(view, g == 0 ? kClarityDarkAlbedo : kClarityBrightAlbedo, uniform);
    media[g] = make_medium(scene_atmosphere(s, body), ReferenceMode::kRgb);
    trace[g] = reference_settings(s, PathBudget(paths)).trace;
  }
  const ColumnTable columns(media[0]);
  std::vector<std::unique_ptr<DepthTable>> depth[2];
  for (int g = 0; g < 2; ++g) {
    for (const MediumChannel& c : media[g].channels) {
      depth[g].push_back(std::make_unique<DepthTable>(columns, c));
    }
  }
  const uint64_t view_seed = view.seed();
  parallel_for(view.height, 0, [&](int y) {
    ClarityRow& row = rows[size_t(y)];
    if (!row.ground) return;
    glm::dvec3 d = row_ray(ref, y);
    glm::dvec3 origin = ref.camera_atmo + (row.range_m - 1.0) * d;
    for (int c = 0; c < 3; ++c) {
      double sum[2] = {0, 0}, diff = 0, diff2 = 0;
      uint64_t seed = reference::mix64(view_seed ^ reference::mix64(uint64_t(y * 3 + c)));
      for (int i = 0; i < paths; ++i) {
        double x[2];
        for (int g = 0; g < 2; ++g) {
          reference::PathSampler sampler(seed, uint32_t(i));
          x[g] = trace_path(*depth[g][size_t(c)], origin, d, ref.sun_dir_atmo, trace[g], sampler);
          sum[g] += x[g];
        }
        diff += x[1] - x[0];
        diff2 += (x[1] - x[0]) * (x[1] - x[0]);
      }
      row.ground_dark[c] = sum[0] / paths;
      row.ground_bright[c] = sum[1] / paths;
      double mean = diff / paths;
      row.ground_noise[c] = std::sqrt(std::max(0.0, diff2 / paths - mean * mean) / paths);
    }
  });
  return rows;
}

glm::dvec3 row_mean(const ImageRGB& image, int row) {
  glm::dvec3 sum(0.0);
  for (int x = 0; x < image.width; ++x) {
    const float* p = &image.pixels[3 * (size_t(row) * size_t(image.width) + size_t(x))];
    sum += glm::dvec3(p[0], p[1], p[2]);
  }
  return sum / double(image.width);
}

glm::dvec3 contrast(const ClarityRow& row, const ImageRGB& dark, const ImageRGB& bright) {
  return (row_mean(bright, row.row) - row_mean(dark, row.row)) /
         (row.ground_bright - row.ground_dark);
}

double visibility_range(const std::vector<ClarityRow>& rows, const std::vector<double>& contrasts,
                        double& at_horizon) {
  // The ground rows from the nearest (the bottom row) to the farthest.
  const ClarityRow* prev = nullptr;
  double prev_c = 0;
  at_horizon = 0;
  for (size_t i = rows.size(); i-- > 0;) {
    if (!rows[i].ground) continue;
    double c = contrasts[i];
    if (c <= kClarityThreshold) {
      if (!prev) return rows[i].range_m;
      // Linear in log(C) against range, as exp(-sigma x) is.
      double a = std::log(std::max(prev_c, 1e-12)), b = std::log(std::max(c, 1e-12));
      double f = (std::log(kClarityThreshold) - a) / (b - a);
      return prev->range_m + f * (rows[i].range_m - prev->range_m);
    }
    prev = &rows[i];
    prev_c = c;
    at_horizon = c;
  }
  return -1.0;
}

std::vector<double> model_transmittance(const std::vector<ClarityRow>& rows, int channel) {
  std::vector<double> t(rows.size(), 0.0);
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].ground) t[i] = std::exp(-rows[i].tau[channel]);
  }
  return t;
}

glm::dvec3 koschmieder_visibility(const AtmosphereModel& model, double altitude_m) {
  return std::log(1.0 / kClarityThreshold) /
         shared::extinction_at(shared::to_shared(model), altitude_m);
}

}  // namespace planet
