#include "lab/gpu/error_model_build.h"

#include "atmosphere/gpu/registry.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "gl/driver_watch.h"
#include "render/frame.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>

namespace planet {

namespace {

// PLANET_CACHE_DIR pointed at an empty folder while it lives: a technique
// that keeps tables on disk builds them from nothing.
class EmptyCache {
 public:
  EmptyCache() {
    if (const char* old = std::getenv("PLANET_CACHE_DIR")) old_ = old, had_ = true;
    char pattern[] = "/tmp/planet-model-change-XXXXXX";
    if (!mkdtemp(pattern)) throw std::runtime_error("cannot make a temporary folder in /tmp");
    dir_ = pattern;
    setenv("PLANET_CACHE_DIR", dir_.c_str(), 1);
  }
  ~EmptyCache() {
    if (had_) {
      setenv("PLANET_CACHE_DIR", old_.c_str(), 1);
    } else {
      unsetenv("PLANET_CACHE_DIR");
    }
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }

 private:
  std::string dir_, old_;
  bool had_ = false;
};

double frame_ms(FrameRenderer& renderer, const Scene& scene) {
  auto start = std::chrono::steady_clock::now();
  renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);
  {
    DriverWait wait("finishing a timed frame");
    glFinish();
  }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

std::string governor_choice(const std::string& technique, const std::string& quality) {
  return quality == "default" ? technique : technique + ":" + quality;
}

double measure_model_change_ms(const Scene& scene, const std::string& choice) {
  EmptyCache empty;
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  FrameRenderer renderer(scene.width, scene.height);
  renderer.set_body(body, model, make_technique(choice));
  frame_ms(renderer, scene);
  std::vector<double> steady;
  for (int i = 0; i < 3; ++i) steady.push_back(frame_ms(renderer, scene));
  std::sort(steady.begin(), steady.end());
  // A model no cache holds: the scattering a millionth stronger.
  AtmosphereModel changed = with_scattering_scaled(model, 1.000001);
  auto start = std::chrono::steady_clock::now();
  renderer.set_atmosphere(changed);
  renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);
  {
    DriverWait wait("finishing a timed model change");
    glFinish();
  }
  double total =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return std::max(total - steady[1], 0.0);
}

std::map<std::string, double> model_change_times(
    const SweepOptions& o, const SweepPlan& plan,
    const std::function<void(const std::string&)>& progress) {
  const std::filesystem::path file = o.out / "model_change.json";
  std::map<std::string, double> times;
  if (!o.redo && std::filesystem::exists(file)) {
    std::ifstream in(file);
    try {
      times = nlohmann::json::parse(in).get<std::map<std::string, double>>();
    } catch (const nlohmann::json::exception& e) {
      throw InputError(fmt::format("{}: not a table of planet lab run ({}); delete it or run "
                                   "with --redo",
                                   file.string(), e.what()));
    }
  }
  if (plan.scenes.empty()) return times;
  Scene scene = plan.scenes.front();
  scene.width = o.time_width;
  scene.height = o.time_height;
  for (const auto& [technique, quality] : plan.points) {
    std::string choice = governor_choice(technique, quality);
    if (times.count(choice)) continue;
    if (progress) progress(choice);
    times[choice] = measure_model_change_ms(scene, choice);
    write_file_atomically(file, nlohmann::json(times).dump(2) + "\n");
  }
  return times;
}

ErrorModel build_error_model(const std::vector<SweepCell>& cells,
                             const std::map<std::string, double>& model_change_ms,
                             const SweepOptions& o, const std::string& source) {
  ErrorModel model;
  model.source = source;
  model.time_width = o.time_width;
  model.time_height = o.time_height;
  model.model_change_ms = model_change_ms;
  for (const SweepCell& cell : cells) {
    auto it = std::find_if(model.classes.begin(), model.classes.end(),
                           [&](const ViewClass& c) { return c.scene == cell.scene; });
    if (it == model.classes.end()) {
      Scene scene = find_scene(cell.scene);
      Body body = scene_body(scene);
      ViewClass c;
      c.scene = cell.scene;
      c.view = view_features(body, scene_atmosphere(scene, body), scene.camera.pos_body,
                             scene.sun_dir_body);
      model.classes.push_back(c);
      it = model.classes.end() - 1;
    }
    ErrorModelEntry e;
    e.choice = governor_choice(cell.technique, cell.quality);
    e.error = cell.error();
    e.error_high = *std::max_element(cell.debiased_high.begin(), cell.debiased_high.end());
    e.frame_ms = cell.wall_ms;
    it->entries.push_back(e);
  }
  return model;
}

}  // namespace planet
