#include "render/capture_shares.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/version.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <utility>

namespace planet {

std::filesystem::path capture_shares_dir(const std::filesystem::path& out) {
  std::filesystem::path dir = out.lexically_normal();
  if (dir.filename().empty()) dir = dir.parent_path();  // "out/ascent/"
  return dir.parent_path() / (dir.filename().string() + ".shares");
}

std::filesystem::path capture_share_dir(const std::filesystem::path& shares_dir,
                                        const Share& share) {
  return shares_dir / fmt::format("share-{}-of-{}", share.index, share.count);
}

std::pair<int, int> capture_share_frames(const FlightScript& script, const Share& share) {
  const int total = script.frame_count();
  if (share.count > total) {
    throw InputError(
        fmt::format("--shard {}: {} has {} frames, too few for {} shares (give at "
                    "most {})",
                    share.label(), script.file.string(), total, share.count, total));
  }
  return share_range(share, total);
}

namespace {

struct CaptureShare {
  std::filesystem::path dir;
  Share share;
  int first = 0, end = 0, total = 0;
  double wall_seconds = 0;
  std::string flight;
  // What the shares of one capture agree on, as (name, value).
  std::vector<std::pair<std::string, std::string>> fields;
};

CaptureShare read_capture_share(const std::filesystem::path& dir) {
  std::filesystem::path file = dir / "capture.json";
  if (!std::filesystem::exists(file)) {
    throw InputError(
        fmt::format("{}: an unfinished share (no capture.json): run it again", dir.string()));
  }
  nlohmann::json j;
  try {
    std::ifstream in(file);
    j = nlohmann::json::parse(in);
    CaptureShare s;
    s.dir = dir;
    if (!j.contains("share")) {
      throw InputError(
          fmt::format("{}: not a share of a capture (no \"share\"; planet capture "
                      "--shard K/N writes one)",
                      file.string()));
    }
    s.share = parse_share(j.at("share").get<std::string>(), file.string() + ": share");
    s.first = j.at("frames").at("first").get<int>();
    s.end = j.at("frames").at("end").get<int>();
    s.total = j.at("frames").at("total_in_flight").get<int>();
    s.wall_seconds = j.at("wall_seconds").get<double>();
    s.flight = j.at("flight").get<std::string>();
    s.fields = {
        {"flight script (hash)", j.at("flight_hash").get<std::string>()},
        {"image size", fmt::format("{}x{}", j.at("image").at("width").get<int>(),
                                   j.at("image").at("height").get<int>())},
        {"frame rate", j.at("frame_rate").dump()},
        {"technique", j.at("technique").get<std::string>()},
        {"frame count", std::to_string(s.total)},
        {"share count", std::to_string(s.share.count)},
        {"planet version", j.at("planet").get<std::string>()},
    };
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a capture's summary: {}", file.string(), e.what()));
  }
}

// The share folders an input names: itself where it holds a capture.json
// or is named share-K-of-N, else its share-K-of-N folders.
std::vector<std::filesystem::path> share_dirs(const std::filesystem::path& input) {
  std::error_code ec;
  if (!std::filesystem::is_directory(input, ec)) {
    throw InputError(fmt::format("--merge {}: no such folder", input.string()));
  }
  std::filesystem::path normal = input.lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();
  if (std::filesystem::exists(input / "capture.json") ||
      normal.filename().string().rfind("share-", 0) == 0) {
    return {input};
  }
  return share_entries(
      input, [](const auto& entry) { return entry.is_directory(); },
      "share-K-of-N folders, written by planet capture --shard K/N");
}

void copy_atomically(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::filesystem::path partial = partial_file(to);
  std::filesystem::copy_file(from, partial, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::rename(partial, to);
}

}  // namespace

MergedCapture merge_capture_shares(const std::vector<std::filesystem::path>& inputs,
                                   const std::filesystem::path& out) {
  if (inputs.empty()) throw InputError("--merge: name the folders of the shares");
  const auto shares = read_shares<CaptureShare>(inputs, share_dirs, read_capture_share);
  // One capture: every share agrees with the most of them, and was made by
  // this program.
  std::vector<ShareOf> of;
  for (const CaptureShare& s : shares) of.push_back({s.dir, s.share, s.fields});
  require_one_job(of);
  for (const CaptureShare& s : shares) {
    if (s.fields.back().second != planet_version()) {
      throw InputError(
          fmt::format("{}: share {} was captured by planet {}, this is planet {}: "
                      "capture it again with this program",
                      s.dir.string(), s.share.label(), s.fields.back().second, planet_version()));
    }
  }
  const int count = shares.front().share.count;
  const int total = shares.front().total;
  std::vector<const CaptureShare*> by_index;
  for (const ShareOf* s : shares_by_index(of, "the capture", inputs)) {
    by_index.push_back(&shares[size_t(s - of.data())]);
  }
  for (const CaptureShare* s : by_index) {
    if (std::make_pair(s->first, s->end) != share_range(s->share, total)) {
      throw InputError(fmt::format("{}: share {} holds frames {}:{}, not its share {}:{}",
                                   s->dir.string(), s->share.label(), s->first, s->end,
                                   share_range(s->share, total).first,
                                   share_range(s->share, total).second));
    }
  }
  // Every frame's files, before anything is copied.
  const std::vector<std::string> kinds = {".exr", ".png", ".json"};
  for (const CaptureShare* s : by_index) {
    for (int frame = s->first; frame < s->end; ++frame) {
      for (const std::string& kind : kinds) {
        std::filesystem::path file = s->dir / fmt::format("frame_{:05d}{}", frame, kind);
        if (!std::filesystem::exists(file)) {
          throw InputError(fmt::format("{}: share {} has no {}", s->dir.string(), s->share.label(),
                                       file.filename().string()));
        }
      }
    }
  }
  // A folder without capture.json is an unfinished capture: it goes first
  // and comes back last.
  std::filesystem::create_directories(out);
  const std::filesystem::path marker = out / "capture.json";
  std::filesystem::remove(marker);
  MergedCapture merged;
  merged.shares = count;
  merged.removed = remove_frames_beyond(out, total);
  for (const CaptureShare* s : by_index) {
    for (int frame = s->first; frame < s->end; ++frame) {
      for (const std::string& kind : kinds) {
        std::string name = fmt::format("frame_{:05d}{}", frame, kind);
        copy_atomically(s->dir / name, out / name);
      }
      ++merged.frames;
    }
    merged.wall_seconds += s->wall_seconds;
  }
  const CaptureShare& first = *by_index.front();
  std::ifstream in(first.dir / "capture.json");
  nlohmann::json summary = nlohmann::json::parse(in);
  summary["frames"] = {{"first", 0}, {"end", total}, {"total_in_flight", total}};
  // What a run at once writes: only the wall time (the shares' together)
  // differs.
  summary["wall_seconds"] = merged.wall_seconds;
  for (const char* key : {"share", "flight_hash", "planet"}) summary.erase(key);
  write_file_atomically(marker, summary.dump(2) + "\n");
  return merged;
}

}  // namespace planet
