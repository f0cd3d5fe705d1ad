#include "lab/reference_cache.h"

#include "core/atomic_file.h"
#include "core/cache_dir.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/parallel.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <utility>

namespace planet {

std::filesystem::path reference_cache_dir() { return cache_dir("reference"); }

std::filesystem::path shipped_reference_dir() { return data_dir() / "reference"; }

std::vector<std::filesystem::path> reference_dirs() {
  std::vector<std::filesystem::path> dirs{reference_cache_dir()};
  std::error_code ec;
  if (!std::filesystem::equivalent(dirs[0], shipped_reference_dir(), ec)) {
    dirs.push_back(shipped_reference_dir());
  }
  return dirs;
}

namespace {

// FNV-1a over the bytes of every value that changes the pixels.
class Hasher : public Fnv1a {
 public:
  void number(double x) { bytes(&x, sizeof x); }
  void vec(const glm::dvec3& v) { number(v.x), number(v.y), number(v.z); }
  void text(const std::string& s) { bytes(s.data(), s.size()), number(double(s.size())); }
  void profile(const DensityProfile& p) {
    for (const auto& l : p.layers) {
      number(l.width), number(l.exp_term), number(l.exp_scale), number(l.linear_term),
          number(l.constant_term);
    }
  }
  void list(const std::vector<double>& v) {
    number(double(v.size()));
    for (double x : v) number(x);
  }
};

}  // namespace

namespace {

// The medium the paths cross: the mode and the model as loaded.
void hash_model(Hasher& h, const AtmosphereModel& m, ReferenceMode mode) {
  h.text(to_string(mode));
  h.number(m.bottom_radius), h.number(m.top_radius), h.vec(m.wavelengths_nm),
      h.vec(m.solar_irradiance), h.number(m.sun_angular_radius), h.number(m.mie_g),
      h.number(m.ground_albedo.g);
  // Added with the derived atmospheres; absent from the hash where they
  // are at their old defaults, so that references cached before stay valid.
  if (m.ground_albedo.r != m.ground_albedo.g || m.ground_albedo.b != m.ground_albedo.g) {
    h.vec(m.ground_albedo);
  }
  if (m.mie_phase != MiePhase::kCornetteShanks) h.text(to_string(m.mie_phase));
  if (m.spectrum && !m.spectrum->ground_albedo.empty()) h.list(m.spectrum->ground_albedo);
  for (const AtmosphereComponent* c : {&m.rayleigh, &m.mie, &m.absorber}) {
    h.vec(c->scattering), h.vec(c->absorption), h.profile(c->density);
  }
  if (m.spectrum) {
    const AtmosphereSpectrum& s = *m.spectrum;
    for (const auto* v : {&s.wavelengths_nm, &s.solar_irradiance, &s.rayleigh_scattering,
                          &s.mie_scattering, &s.mie_absorption, &s.absorber_absorption}) {
      h.list(*v);
    }
  }
}

// Everything but the tracer's version and the paths.
void hash_view(Hasher& h, const Scene& scene, const AtmosphereModel& m, ReferenceMode mode) {
  hash_model(h, m, mode);
  h.text(scene.name), h.text(scene.body);
  h.vec(scene.camera.pos_body), h.vec(scene.sun_dir_body);
  h.number(scene.camera.body_from_camera.w), h.number(scene.camera.body_from_camera.x),
      h.number(scene.camera.body_from_camera.y), h.number(scene.camera.body_from_camera.z);
  h.number(scene.camera.vertical_fov), h.number(scene.width), h.number(scene.height);
  h.number(scene.projection == Projection::kPerspective ? 0 : 1);
  // Only where limited, so that the keys of the full ground truth stand.
  if (scene.max_order > 0) h.text("max order"), h.number(scene.max_order);
  if (scene.target_albedo) h.text("target albedo"), h.number(*scene.target_albedo);
  if (scene.moon_radius > 0.0) {
    h.text("moon"), h.vec(scene.moon_pos_body), h.number(scene.moon_radius);
  }
}

}  // namespace

std::string reference_key(const Scene& scene, const AtmosphereModel& m, const PathBudget& paths,
                          ReferenceMode mode) {
  Hasher h;
  h.number(kReferenceVersion);
  if (paths.per_channel.empty()) {
    h.number(paths.spp);
  } else {
    h.text("per channel");
    for (int n : paths.per_channel) h.number(n);
  }
  hash_view(h, scene, m, mode);
  return fmt::format("{:016x}", h.value());
}

std::string reference_view_key(const Scene& scene, const AtmosphereModel& m, ReferenceMode mode) {
  Hasher h;
  h.number(kReferenceVersion);
  h.text("any paths");
  hash_view(h, scene, m, mode);
  return fmt::format("{:016x}", h.value());
}

std::string reference_model_key(const AtmosphereModel& m, ReferenceMode mode) {
  Hasher h;
  hash_model(h, m, mode);
  return fmt::format("{:016x}", h.value());
}

std::filesystem::path reference_cache_file(const Scene& scene, const AtmosphereModel& model,
                                           const PathBudget& paths, ReferenceMode mode) {
  return reference_cache_dir() / fmt::format("{}-{}spp-{}-{}.exr", reference_stem(scene),
                                             paths.label(), to_string(mode),
                                             reference_key(scene, model, paths, mode));
}

ImageRGB to_image_rgb(const ReferenceImage& image) {
  ImageRGB out;
  out.width = image.width;
  out.height = image.height;
  out.pixels = image.rgb;
  return out;
}

std::filesystem::path reference_noise_file(const std::filesystem::path& reference_file) {
  return std::filesystem::path(reference_file).replace_extension(".noise.exr");
}

std::filesystem::path reference_sums_file(const std::filesystem::path& reference_file) {
  return std::filesystem::path(reference_file).replace_extension(".sums");
}

namespace {

// A whole reference (image and noise) of this file name, in the cache or
// among the shipped ones.
std::optional<std::filesystem::path> find_whole(const std::filesystem::path& name) {
  for (const std::filesystem::path& dir : reference_dirs()) {
    std::filesystem::path file = dir / name;
    if (std::filesystem::exists(file) && std::filesystem::exists(reference_noise_file(file))) {
      return file;
    }
  }
  return std::nullopt;
}

// The sums in the cache a render of this view and budget can go on from:
// of the same view, with no more paths in any lane than the budget gives
// it; of those, the one furthest along.
std::optional<std::pair<std::filesystem::path, RenderSums>> find_start(
    const Scene& scene, const std::string& view_key, ReferenceMode mode,
    const std::vector<int>& lane_paths) {
  std::optional<std::pair<std::filesystem::path, RenderSums>> best;
  std::error_code ec;
  std::string prefix = reference_stem(scene) + "-";
  std::string mode_part = fmt::format("spp-{}-", to_string(mode));
  for (const std::filesystem::path& dir : reference_dirs()) {
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      std::string name = entry.path().filename().string();
      if (entry.path().extension() != ".sums" || name.rfind(prefix, 0) != 0 ||
          name.find(mode_part) == std::string::npos) {
        continue;
      }
      std::optional<RenderSums> sums = read_sums(entry.path(), view_key);
      if (sums && sums->fits(lane_paths) && (!best || sums->traced() > best->second.traced())) {
        best.emplace(entry.path(), std::move(*sums));
      }
    }
  }
  return best;
}

}  // namespace

ReferenceRender reference_render(const Scene& scene, const PathBudget& paths, ReferenceMode mode,
                                 const std::function<void(double)>& progress,
                                 const std::atomic<bool>* cancel) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  std::filesystem::path file = reference_cache_file(scene, model, paths, mode);
  if (std::optional<std::filesystem::path> found = find_whole(file.filename())) {
    return {read_image_rgb(*found), read_image_rgb(reference_noise_file(*found)), {}, 0.0};
  }
  std::filesystem::path noise_file = reference_noise_file(file);
  Medium medium = make_medium(model, mode);
  std::vector<int> lane_paths = paths.lane_paths(medium.channels.size());
  std::string view_key = reference_view_key(scene, model, mode);
  std::filesystem::path sums_file = reference_sums_file(file);
  std::filesystem::create_directories(file.parent_path());
  // What a render killed while writing its sums or images left.
  remove_stale_partials(file.parent_path());
  ReferenceSettings settings = reference_settings(scene, paths);
  settings.progress = progress;
  settings.cancel = cancel;
  bool checkpointed = false;
  settings.checkpoint = [&](const RenderSums& sums) {
    write_sums(sums_file, view_key, sums);
    checkpointed = true;
  };
  auto start = find_start(scene, view_key, mode, lane_paths);
  double share = 0.0;
  if (start) {
    settings.start = &start->second;
    double all = 0;
    for (int n : lane_paths) all += n;
    share = double(start->second.traced()) / all;
  }
  ReferenceImage image;
  try {
    image = render_reference(medium, reference_view(scene, body, model), settings);
  } catch (const RenderInterrupted& e) {
    std::string kept =
        checkpointed ? sums_file.string() : (start ? start->first.string() : std::string());
    if (kept.empty()) {
      throw ReferenceInterrupted(fmt::format(
          "interrupted before the first checkpoint of {}: no paths were kept", scene.name));
    }
    throw ReferenceInterrupted(
        fmt::format("interrupted: {:.1f}% of the paths of {} are kept in {}; run the same command "
                    "again to go on",
                    100.0 * e.kept_share, scene.name, kept));
  }
  ReferenceRender out{to_image_rgb(image),
                      {image.width, image.height, image.noise},
                      start ? start->first : std::filesystem::path(),
                      share};
  // The noise first: a reference in the cache always has its noise.
  write_exr(noise_file, out.noise);
  write_exr(file, out.image);
  return out;
}

bool reference_cached(const Scene& scene, const PathBudget& paths, ReferenceMode mode) {
  AtmosphereModel model = scene_atmosphere(scene, scene_body(scene));
  return find_whole(reference_cache_file(scene, model, paths, mode).filename()).has_value();
}

std::optional<PathBudget> best_cached_budget(const Scene& scene, ReferenceMode mode) {
  AtmosphereModel model = scene_atmosphere(scene, scene_body(scene));
  std::string prefix = reference_stem(scene) + "-";
  std::string suffix = fmt::format("spp-{}-", to_string(mode));
  std::optional<PathBudget> best;
  double best_paths = 0;
  std::error_code ec;
  for (const std::filesystem::path& dir : reference_dirs()) {
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || name.ends_with(".noise.exr") || !name.ends_with(".exr")) {
      continue;
    }
    size_t at = name.find(suffix, prefix.size());
    if (at == std::string::npos) continue;
    PathBudget budget;
    try {
      budget = PathBudget::parse(name.substr(prefix.size(), at - prefix.size()));
    } catch (const InputError&) {
      continue;  // not a name the cache writes
    }
    // Of this view and model (the key says so), and whole.
    if (reference_cache_file(scene, model, budget, mode).filename() != name) continue;
    if (!std::filesystem::exists(reference_noise_file(entry.path()))) continue;
    double paths = budget.per_channel.empty() ? double(budget.spp) : 0.0;
    for (int n : budget.per_channel) paths += n;
    if (!best || paths > best_paths) {
      best = budget;
      best_paths = paths;
    }
  }
  }
  return best;
}

RenderCost estimate_reference_cost(const Scene& scene, const PathBudget& paths,
                                   ReferenceMode mode) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  Medium medium = make_medium(model, mode);
  const size_t channels = medium.channels.size();
  std::vector<int> lanes = paths.lane_paths(channels);
  double per_pixel = 0;
  for (int n : lanes) per_pixel += n;
  // A trial with the budget's proportions between channels, about 64
  // paths per pixel in all.
  double scale = std::min(1.0, 64.0 / per_pixel);
  std::vector<int> trial_counts;
  for (size_t c = 0; c < channels; ++c) {
    double n = paths.per_channel.empty() ? double(paths.spp) / double(channels)
                                         : double(paths.per_channel[c]);
    trial_counts.push_back(std::max(kReplicates, int(std::lround(n * scale))));
  }
  ReferenceSettings trial = reference_settings(scene, PathBudget(trial_counts));
  ReferenceImage image = render_reference(medium, reference_view(scene, body, model), trial);
  double trial_paths = double(image.paths);
  double pixels = double(scene.width) * double(scene.height);
  RenderCost cost;
  cost.threads = thread_count(0);
  cost.paths = per_pixel * pixels;
  std::string view_key = reference_view_key(scene, model, mode);
  if (auto start = find_start(scene, view_key, mode, lanes)) {
    cost.already_done = double(start->second.traced()) / per_pixel;
  }
  double rate = trial_paths / std::max(image.trace_seconds, 1e-6);
  cost.seconds =
      (image.seconds - image.trace_seconds) + cost.paths * (1.0 - cost.already_done) / rate;
  return cost;
}

std::string describe_uncached_reference(const Scene& scene, const PathBudget& paths,
                                        ReferenceMode mode, const RenderCost& cost) {
  auto duration = [](double s) {
    return s < 90     ? fmt::format("{:.0f} s", s)
           : s < 5400 ? fmt::format("{:.1f} min", s / 60)
                      : fmt::format("{:.1f} h", s / 3600);
  };
  std::string went_on =
      cost.already_done > 0
          ? fmt::format(", going on from sums that hold {:.1f}% of it", 100.0 * cost.already_done)
          : "";
  std::string orders =
      scene.max_order > 0 ? fmt::format(", up to {} orders of scattering", scene.max_order) : "";
  return fmt::format(
      "no reference of {} ({}x{}, {} paths per pixel, {}{}) is cached in {}: rendering it{} takes "
      "about {} on {} threads; it is cached for next time, and Ctrl-C keeps what is done",
      scene.name, scene.width, scene.height, paths.label(), to_string(mode), orders,
      reference_cache_dir().string(), went_on, duration(cost.seconds), cost.threads);
}

ImageRGB reference_image(const Scene& scene, const PathBudget& paths, ReferenceMode mode,
                         const std::function<void(double)>& progress) {
  return reference_render(scene, paths, mode, progress).image;
}

}  // namespace planet
