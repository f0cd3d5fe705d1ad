#include "render/capture.h"

#include "atmosphere/gpu/registry.h"
#include "clouds/cloud_model.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/image_io.h"
#include "core/interrupt.h"
#include "core/progress.h"
#include "core/version.h"
#include "governor/governor.h"
#include "render/frame.h"
#include "render/technique_switch.h"
#include "sim/eclipse.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace planet {

namespace {

// Generous: the deepest view (2 m above mountains) builds a few hundred
// tiles, seconds on one core.
constexpr double kTerrainWaitSeconds = 300.0;

// The image's settings as the sidecars and capture.json give them.
nlohmann::json image_json(const FlightScript& script) {
  nlohmann::json image = {{"width", script.width},
                          {"height", script.height},
                          {"antialiasing", script.antialiasing},
                          {"terrain_shadows", script.terrain_shadows},
                          {"stars", script.stars}};
  // Only when asked: a capture without glare keeps the bytes it had.
  if (script.glare) image["glare"] = true;
  if (script.clouds) image["clouds"] = true;
  return image;
}

nlohmann::json sidecar(const FlightScript& script, const FlightPath& path, const Geodesy& geodesy,
                       int frame, double t, const Camera& camera, double exposure,
                       const glm::dvec3& sun, const FrameStats& stats,
                       const TerrainStats& terrain, const std::string& technique) {
  Geodetic g = geodesy.geodetic_from_body(camera.pos_body);
  // The passes that ran, with their GPU time, and those whose last result
  // still held and was reused.
  nlohmann::json passes = nlohmann::json::object();
  nlohmann::json reused = nlohmann::json::array();
  for (const auto& p : stats.passes) {
    if (p.skipped) continue;
    if (p.reused) {
      reused.push_back(p.pass);
    } else {
      passes[p.pass] = p.gpu_ms;
    }
  }
  const glm::dquat& q = camera.body_from_camera;
  nlohmann::json j = {
      {"frame", frame},
      {"time_s", t},
      {"body", script.body.name},
      {"camera",
       {{"position_body_m", {camera.pos_body.x, camera.pos_body.y, camera.pos_body.z}},
        {"lat_deg", glm::degrees(g.lat)},
        {"lon_deg", glm::degrees(g.lon)},
        {"height_m", g.height},
        {"body_from_camera_wxyz", {q.w, q.x, q.y, q.z}},
        {"vertical_fov_deg", glm::degrees(camera.vertical_fov)}}},
      {"sun_dir_body", {sun.x, sun.y, sun.z}},
      {"technique", technique},
      {"exposure", exposure},
      {"exposure_mode", script.auto_exposure ? "auto" : "script"},
      {"image", image_json(script)},
      {"gpu_ms", passes},
      {"passes_reused", reused},
      {"terrain",
       {{"tiles_drawn", terrain.tiles_drawn},
        {"triangles", terrain.triangles},
        {"tiles_resident", terrain.tiles_resident},
        {"bytes_resident", terrain.bytes_resident},
        {"max_error_px", terrain.max_error_px},
        {"deepest_level", terrain.max_level}}},
  };
  if (script.has_clock) j["utc"] = format_utc(path.utc_at(t));
  // Where the Moon (or, over the Moon, the Earth) really is then.
  if (auto other = path.companion_pos_at(t)) {
    j[fmt::format("{}_pos_body_m",
                  script.body.ephemeris.model == SunEphemeris::Model::kEarth ? "moon" : "earth")] =
        {other->x, other->y, other->z};
  }
  return j;
}

}  // namespace

TechniqueChoice script_technique(const FlightScript& script) {
  try {
    return parse_technique(script.technique);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: technique: {}", script.file.string(), e.what()));
  }
}

namespace {

// The sidecar's fields as "planet:" header attributes: nested objects
// joined with ':', numbers as doubles, three numbers as a vector, anything
// else as its JSON text. But for those that are not the frame's own: its
// timings (GPU and wall, which differ run to run), and what the tile cache
// holds and which passes were reused (which depend on the frames rendered
// before it, so on the --frames slice).
void add_sidecar_attributes(const nlohmann::json& j, const std::string& prefix,
                            std::vector<ImageAttribute>& out) {
  for (const auto& [key, value] : j.items()) {
    if (prefix == "planet:" &&
        (key == "gpu_ms" || key == "wall_seconds" || key == "passes_reused")) {
      continue;
    }
    if (prefix == "planet:terrain:" && (key == "tiles_resident" || key == "bytes_resident")) {
      continue;
    }
    std::string name = prefix + key;
    if (value.is_object()) {
      add_sidecar_attributes(value, name + ":", out);
    } else if (value.is_number()) {
      out.push_back({name, value.get<double>()});
    } else if (value.is_string()) {
      out.push_back({name, value.get<std::string>()});
    } else if (value.is_array() && value.size() == 3 && value[0].is_number()) {
      out.push_back({name, glm::dvec3(value[0].get<double>(), value[1].get<double>(),
                                      value[2].get<double>())});
    } else {
      out.push_back({name, value.dump()});
    }
  }
}

// What a compositor reads from a frame: the OpenEXR standard attributes of
// place, time and camera, from the frame's own state (so that the bytes
// stay the same run to run), the sidecar as "planet:" attributes, and the
// depth channel.
ExrExtras frame_exr_extras(const FlightScript& script, const FlightPath& path, double t,
                           const Camera& camera, const nlohmann::json& sidecar,
                           const FrameRenderer& renderer) {
  ExrExtras extras;
  auto& a = extras.attributes;
  if (script.has_clock) {
    // capDate is local time as "YYYY:MM:DD HH:MM:SS"; the clock is UTC.
    std::string utc = format_utc(path.utc_at(t));  // 2026-06-21T12:00:00.000Z
    std::string date = utc.substr(0, 19);
    date[4] = date[7] = ':';
    date[10] = ' ';
    a.push_back({"DateTime", date});
    a.push_back({"utcOffset", 0.0f});
  }
  Geodetic g = Geodesy(script.body.shape).geodetic_from_body(camera.pos_body);
  a.push_back({"latitude", float(glm::degrees(g.lat))});
  a.push_back({"longitude", float(glm::degrees(g.lon))});
  a.push_back({"altitude", float(g.height)});
  // The body frame is the world: camera from body, then clip from camera.
  glm::dmat3 camera_from_body = glm::mat3_cast(glm::conjugate(camera.body_from_camera));
  glm::dmat4 world_to_camera(camera_from_body);
  world_to_camera[3] = glm::dvec4(-(camera_from_body * camera.pos_body), 1.0);
  glm::mat4 clip = clip_from_view_reversed_z(camera.vertical_fov,
                                             double(script.width) / script.height, camera.near);
  a.push_back({"worldToCamera", glm::mat4(world_to_camera)});
  a.push_back({"worldToNDC", clip * glm::mat4(world_to_camera)});
  add_sidecar_attributes(sidecar, "planet:", a);
  extras.depth = renderer.read_distance(camera);
  return extras;
}

}  // namespace

void check_frames(const FlightScript& script, const CaptureOptions& options) {
  const int total = script.frame_count();
  const int first = options.first_frame;
  const int end = options.end_frame < 0 ? total : options.end_frame;
  if (first >= end) {
    throw InputError(
        fmt::format("--frames {}:{} is empty or reversed: the first frame must come "
                    "before the end (one past the last)",
                    first, end));
  }
  if (first < 0 || end > total) {
    throw InputError(fmt::format("{}: --frames {}:{} lies outside the flight's frames 0:{}",
                                 script.file.string(), first, end, total));
  }
}

std::string flight_script_hash(const FlightScript& script) {
  std::ifstream in(script.file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return fmt::format("{:016x}", fnv1a(text.str()));
}

void check_keyframes_above_ground(const FlightScript& script, const GroundHeight& ground) {
  if (script.allow_below_ground) return;
  for (size_t i = 0; i < script.keyframes.size(); ++i) {
    const Keyframe& k = script.keyframes[i];
    double ground_m = ground(script.body, k.place);
    if (k.place.height < ground_m) {
      std::string given = k.height_above_ground
                              ? fmt::format("height_above_ground_m {:.1f}", *k.height_above_ground)
                              : fmt::format("height_m {:.1f}", k.place.height);
      throw InputError(fmt::format(
          "{}: keyframes[{}]: the camera is {:.1f} m below the ground ({}, the ground {:.1f} m "
          "above the ellipsoid there; planet probe ground gives it): raise it, or set "
          "\"allow_below_ground\": true",
          script.file.string(), i, ground_m - k.place.height, given, ground_m));
    }
  }
}

std::optional<double> capture_error_budget(const FlightScript& script,
                                           const CaptureOptions& options) {
  if (script.technique_named || !script.body.has_atmosphere()) return std::nullopt;
  return options.error_budget_percent ? options.error_budget_percent : script.error_budget_percent;
}

CapturePlan plan_capture(const FlightScript& script, const CaptureOptions& options) {
  check_frames(script, options);
  if (script.body.has_atmosphere()) script_technique(script);
  CapturePlan plan;
  plan.total = script.frame_count();
  plan.first = options.first_frame;
  plan.end = options.end_frame < 0 ? plan.total : options.end_frame;
  plan.budget = capture_error_budget(script, options);
  if (plan.budget) {
    plan.error_model = load_error_model(
        options.error_model_file.empty() ? shipped_error_model_file() : options.error_model_file);
  }
  return plan;
}

namespace {

// The governor the plan's budget runs, with the table the plan read.
std::optional<Governor> capture_governor(const FlightScript& script, const CaptureOptions& options,
                                         const CapturePlan& plan) {
  if (!plan.budget) return std::nullopt;
  GovernorSettings settings;
  settings.budget_percent = *plan.budget;
  // The model is the flight's throughout: its tables are built once.
  settings.frames_per_model = plan.total;
  // A switch waits half a second of the flight and fades over one, in at
  // least a few frames.
  settings.dwell_frames = std::max(3, int(std::lround(0.5 * script.frame_rate)));
  settings.fade_frames = options.switch_fade_frames > 0
                             ? options.switch_fade_frames
                             : std::max(4, int(std::lround(1.0 * script.frame_rate)));
  return Governor(*plan.error_model, settings, script.technique);
}

// The renderer as the script sets it, drawing every tile a view needs.
void set_up_renderer(FrameRenderer& renderer, const FlightScript& script,
                     const CaptureOptions& options) {
  FrameOptions frame_options;
  frame_options.antialiasing = script.antialiasing;
  frame_options.terrain_shadows = script.terrain_shadows;
  frame_options.stars = script.stars;
  frame_options.glare = script.glare;
  frame_options.clouds = script.clouds;
  frame_options.auto_exposure = script.auto_exposure;
  frame_options.terrain.pixel_budget = options.pixel_budget;
  frame_options.terrain.cache_bytes = options.terrain_cache_bytes;
  // A capture draws every tile the view needs at its level: frames must
  // not depend on how fast tiles happened to be built.
  frame_options.terrain_wait_s = kTerrainWaitSeconds;
  frame_options.synchronous_timing = options.pass_table;
  renderer.set_options(frame_options);
}

// The folder made ready for the slice: unfinished until capture.json comes
// back last, with no half-written file and no frame without its sidecar.
// Frames beyond this flight's last are an earlier, longer capture's: no
// slice of this one writes them, and they would make the folder look like
// more than it is.
FramesBeyond prepare_capture_folder(const CaptureOptions& options, const CapturePlan& plan) {
  std::filesystem::create_directories(options.out_dir);
  std::filesystem::remove(options.out_dir / "capture.json");
  remove_stale_partials(options.out_dir);
  remove_frames_without_sidecar(options.out_dir, plan.first, plan.end);
  return remove_frames_beyond(options.out_dir, plan.total);
}

// The frame's files, each whole, made in the staging folder and then moved
// into place together, the sidecar last: a capture killed at any moment
// leaves whole frames, and a frame without its sidecar is not one (resume
// from the first of those).
void publish_frame(const StagingFolder& staging, const FlightScript& script, const FlightPath& path,
                   double t, const Camera& camera, nlohmann::json& side, FrameRenderer& renderer,
                   const std::string& stem, std::chrono::steady_clock::time_point& frame_start) {
  try {
    write_exr(staging.path() / (stem + ".exr"), script.width, script.height, renderer.read_hdr(),
              frame_exr_extras(script, path, t, camera, side, renderer));
    write_png(staging.path() / (stem + ".png"), script.width, script.height, renderer.read_ldr());
    // The frame's time, from the end of the one before: the sum over a
    // folder's frames is the time its runs spent on them (capture.json).
    auto now = std::chrono::steady_clock::now();
    side["wall_seconds"] = std::chrono::duration<double>(now - frame_start).count();
    frame_start = now;
    write_file_atomically(staging.path() / (stem + ".json"), side.dump(2) + "\n");
  } catch (const SystemError& e) {
    throw SystemError(staging.as_published(e.what()));
  }
  for (const char* extension : {".exr", ".png", ".json"}) staging.publish(stem + extension);
}

// capture.json describes the folder: this run's frames and those earlier
// runs (an interrupted one, the slices before) left beside them whole, of
// this capture, and the time they all took. A share keeps to its own
// frames.
void write_capture_summary(const FlightScript& script, const CaptureOptions& options,
                           const CapturePlan& plan, const FlightPath& path,
                           const nlohmann::json& overrides, CaptureResult& result) {
  const nlohmann::json image = image_json(script);
  auto of_this_capture = [&](int frame, const nlohmann::json& side) {
    double t = script.frame_time(frame);
    glm::dvec3 pos = path.camera_at(t).pos_body;
    return side.at("frame") == frame && side.at("time_s") == t &&
           side.at("body") == script.body.name && side.at("image") == image &&
           side.at("camera").at("position_body_m") == nlohmann::json{pos.x, pos.y, pos.z} &&
           (plan.budget || side.at("technique") == script.technique) &&
           side.value("overrides", nlohmann::json::object()) == overrides;
  };
  const std::pair<int, int> bounds =
      options.share.whole() ? std::pair{0, plan.total} : std::pair{plan.first, plan.end};
  result.folder = whole_frames_around(options.out_dir, plan.first, plan.end, bounds.first,
                                      bounds.second, of_this_capture);
  nlohmann::json summary = {
      {"flight", script.file.string()},
      {"frames",
       {{"first", result.folder.first},
        {"end", result.folder.end},
        {"total_in_flight", plan.total}}},
      {"frame_rate", script.frame_rate},
      {"image", image},
      {"technique",
       plan.budget ? fmt::format("governor, budget {:g} %", *plan.budget) : script.technique},
      {"wall_seconds", result.folder.wall_seconds},
  };
  if (!overrides.empty()) summary["overrides"] = overrides;
  // A share says what it is a share of, for the merge (capture_shares.h);
  // the merged capture.json is again the one a run at once writes.
  if (!options.share.whole()) {
    summary["share"] = options.share.label();
    summary["flight_hash"] = flight_script_hash(script);
    summary["planet"] = planet_version();
  }
  write_file_atomically(options.out_dir / "capture.json", summary.dump(2) + "\n");
}

}  // namespace

CaptureResult run_capture(const FlightScript& script, const CaptureOptions& options) {
  return run_capture(script, options, plan_capture(script, options));
}

CaptureResult run_capture(const FlightScript& script, const CaptureOptions& options,
                          const CapturePlan& plan) {
  const int first = plan.first, end = plan.end, total = plan.total;
  std::optional<Governor> governor = capture_governor(script, options, plan);
  std::optional<AtmosphereModel> atmosphere;
  std::unique_ptr<AtmosphereTechnique> technique;
  if (script.body.has_atmosphere()) {
    atmosphere = load_atmosphere(script.body);
    load_clouds(script.body);  // its errors before any frame
    if (!governor) technique = make_technique(script_technique(script));
  }
  CaptureResult result;
  result.removed = prepare_capture_folder(options, plan);
  StagingFolder staging(options.out_dir);

  FrameRenderer renderer(script.width, script.height);
  set_up_renderer(renderer, script, options);
  renderer.set_body(script.body, atmosphere, std::move(technique));
  FlightPath path(script);
  Geodesy geodesy(script.body.shape);
  std::optional<TechniqueSwitch> switcher;
  auto decide = [&](int frame) {
    double t = script.frame_time(frame);
    return governor->decide(
        view_features(script.body, *atmosphere, path.camera_at(t).pos_body, path.sun_dir_at(t)));
  };
  if (governor) {
    switcher.emplace(renderer, "");
    // The frames before the slice, decided but not drawn: the governor's
    // hysteresis and fades count frames, and a slice must choose as the
    // whole run does.
    for (int frame = 0; frame < first; ++frame) decide(frame);
  }

  const nlohmann::json overrides = overrides_json(options.overrides);
  Progress progress("capture " + script.name, end - first, "frame", !options.progress);
  // Ctrl-C: the frame in progress is finished, then the capture stops.
  InterruptScope interrupt;
  auto start = std::chrono::steady_clock::now();
  auto frame_start = start;
  for (int frame = first; frame < end; ++frame) {
    if (interrupt.interrupted()) {
      progress.finish();
      throw CaptureInterrupted(
          fmt::format("interrupted: frames {} to {} are complete in {}; resume with --frames {}:{}",
                      first, frame - 1, options.out_dir.string(), frame,
                      end == total ? std::string() : std::to_string(end)));
    }
    double t = script.frame_time(frame);
    Camera camera = path.camera_at(t);
    double exposure = path.exposure_at(t);
    glm::dvec3 sun = path.sun_dir_at(t);
    std::optional<GovernorDecision> decision;
    if (governor) {
      decision = decide(frame);
      switcher->apply(*decision, *atmosphere);
    }
    renderer.set_star_orientation(body_from_icrf(script.body, path.utc_at(t)));
    // Over the Earth with a clock, the Moon where it really is: before the
    // sun in an eclipse, for the techniques that take it.
    if (script.body.ephemeris.model == SunEphemeris::Model::kEarth) {
      if (std::optional<glm::dvec3> moon = path.companion_pos_at(t)) {
        const EclipseConstants c;
        renderer.set_moon(*moon, c.moon_k_mean * c.earth_radius);
      }
    }
    FrameStats stats = renderer.render(camera, sun, exposure);
    result.passes.add(stats.passes);
    exposure = renderer.last_exposure();
    std::string stem = frame_stem(frame);
    nlohmann::json side = sidecar(script, path, geodesy, frame, t, camera, exposure, sun, stats,
                                  renderer.terrain_stats(),
                                  decision ? decision->choice : script.technique);
    if (decision) side["governor"] = decision->to_json(*plan.budget);
    if (!overrides.empty()) side["overrides"] = overrides;
    publish_frame(staging, script, path, t, camera, side, renderer, stem, frame_start);
    if (frame == first) result.first_png = options.out_dir / (stem + ".png");
    result.last_png = options.out_dir / (stem + ".png");
    ++result.frames;
    progress.update(frame + 1 - first);
  }
  // No staging left for a kill to find from here on: writing the summary
  // and tearing down GL took long enough for the kill test to land there.
  staging.remove();
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  write_capture_summary(script, options, plan, path, overrides, result);
  return result;
}

}  // namespace planet
