#include "sim/flight_recorder.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <fmt/format.h>

#include <fstream>

namespace planet {

FlightRecorder::FlightRecorder(std::string body, std::string technique, int width, int height,
                               double vertical_fov_deg, double frame_rate, UtcSeconds start)
    : frame_rate_(frame_rate) {
  script_ = {
      {"body", body},
      {"image", {{"width", width}, {"height", height}}},
      {"frame_rate", frame_rate},
      {"vertical_fov_deg", vertical_fov_deg},
      {"technique", technique},
      {"start_utc", format_utc(start)},
      {"keyframes", nlohmann::json::array()},
  };
}

void FlightRecorder::add(const Camera& camera, double clock_s, double exposure) {
  const glm::dquat& q = camera.body_from_camera;
  script_["keyframes"].push_back({
      {"time", next_frame_time()},
      {"position_body_m", {camera.pos_body.x, camera.pos_body.y, camera.pos_body.z}},
      {"body_from_camera_wxyz", {q.w, q.x, q.y, q.z}},
      {"clock_s", clock_s},
      {"exposure", exposure},
  });
  ++frames_;
}

nlohmann::json FlightRecorder::script() const {
  nlohmann::json s = script_;
  // A script needs an exposure; the keyframes carry their own.
  s["exposure"] = frames_ > 0 ? s["keyframes"][0]["exposure"] : nlohmann::json(1.0);
  return s;
}

void FlightRecorder::write(const std::filesystem::path& file) const {
  if (frames_ == 0) throw InputError("nothing recorded");
  // Whole or not at all: a full disk or a kill never leaves half a flight.
  write_file_atomically(file, script().dump(2) + "\n");
}

}  // namespace planet
