#include "render/capture_folder.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <vector>

namespace planet {

std::string frame_stem(int frame) { return fmt::format("frame_{:05d}", frame); }

namespace {

bool is_frame_extension(const std::string& ext) {
  return ext == ".exr" || ext == ".png" || ext == ".json";
}

// The frame a file of the folder belongs to, from its name, or -1 for
// anything else (capture.json, a partial file, a staging folder).
int frame_of_file(const std::filesystem::path& file) {
  std::string name = file.filename().string(), ext = file.extension().string();
  int frame = -1;
  if (!is_frame_extension(ext) || std::sscanf(name.c_str(), "frame_%d.", &frame) != 1 ||
      frame < 0 || name != frame_stem(frame) + ext) {
    return -1;
  }
  return frame;
}

}  // namespace

void remove_frames_without_sidecar(const std::filesystem::path& dir, int first, int end) {
  std::error_code ec;
  std::vector<std::filesystem::path> orphans;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::filesystem::path& file = entry.path();
    int frame = frame_of_file(file);
    if (frame < first || frame >= end || file.extension() == ".json") continue;
    std::filesystem::path side = file;
    side.replace_extension(".json");
    if (!std::filesystem::exists(side, ec)) orphans.push_back(file);
  }
  for (const auto& file : orphans) std::filesystem::remove(file, ec);
}

FramesBeyond remove_frames_beyond(const std::filesystem::path& dir, int total) {
  std::error_code ec;
  std::vector<std::filesystem::path> files;
  std::set<int> frames;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    int frame = frame_of_file(entry.path());
    if (frame < total) continue;
    files.push_back(entry.path());
    frames.insert(frame);
  }
  // The sidecars first: a frame without its sidecar is no frame, should
  // this stop half-way.
  for (const auto& file : files) {
    if (file.extension() == ".json") std::filesystem::remove(file);
  }
  for (const auto& file : files) {
    if (file.extension() != ".json") std::filesystem::remove(file);
  }
  FramesBeyond beyond;
  beyond.count = int(frames.size());
  if (!frames.empty()) {
    beyond.first = *frames.begin();
    beyond.last = *frames.rbegin();
  }
  return beyond;
}

FolderFrames whole_frames_around(
    const std::filesystem::path& dir, int run_first, int run_end, int lowest, int highest,
    const std::function<bool(int frame, const nlohmann::json& sidecar)>& of_capture) {
  // The seconds a whole frame of this capture took, or none.
  auto whole = [&](int frame) -> std::optional<double> {
    std::string stem = frame_stem(frame);
    std::error_code ec;
    for (const char* ext : {".exr", ".png", ".json"}) {
      if (!std::filesystem::exists(dir / (stem + ext), ec)) return std::nullopt;
    }
    try {
      std::ifstream in(dir / (stem + ".json"));
      nlohmann::json sidecar = nlohmann::json::parse(in);
      if (!of_capture(frame, sidecar)) return std::nullopt;
      const nlohmann::json& seconds = sidecar.value("wall_seconds", nlohmann::json(0.0));
      return seconds.is_number() ? seconds.get<double>() : 0.0;
    } catch (const nlohmann::json::exception&) {
      return std::nullopt;
    }
  };
  FolderFrames folder{run_first, run_end, 0.0};
  for (int frame = run_first; frame < run_end; ++frame) {
    folder.wall_seconds += whole(frame).value_or(0.0);
  }
  for (std::optional<double> s; folder.first > lowest && (s = whole(folder.first - 1));) {
    --folder.first;
    folder.wall_seconds += *s;
  }
  for (std::optional<double> s; folder.end < highest && (s = whole(folder.end));) {
    ++folder.end;
    folder.wall_seconds += *s;
  }
  return folder;
}

}  // namespace planet
