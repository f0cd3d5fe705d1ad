#include "lab/reference_merge.h"

#include "core/error.h"
#include "core/image_io.h"
#include "core/version.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace planet {

namespace {

// The share files an input names: the file itself, or a folder's
// share-K-of-N.sums in name order.
std::vector<std::filesystem::path> share_files(const std::filesystem::path& input) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(input, ec)) return {input};
  if (!std::filesystem::is_directory(input, ec)) {
    throw InputError(fmt::format("--merge {}: no such file or folder", input.string()));
  }
  return share_entries(
      input, [](const auto& entry) { return entry.path().extension() == ".sums"; },
      "share-K-of-N.sums, written by planet reference --shard K/N");
}

// What the shares of one render must agree on, as (name, value): those a
// merge takes from the shares themselves.
std::vector<std::pair<std::string, std::string>> shared_fields(const ReferenceShareId& id) {
  return {{"scene", id.scene},
          {"size", fmt::format("{}x{}", id.width, id.height)},
          {"mode", id.mode},
          {"orders", id.max_order > 0 ? std::to_string(id.max_order) : "all"},
          {"spp", id.paths},
          {"share count", std::to_string(id.share.count)}};
}

// ... and those this program fixes: a share of another model or build
// would not give the bits this program renders.
std::vector<std::pair<std::string, std::string>> program_fields(const ReferenceShareId& id) {
  return {{"tracer version", std::to_string(id.tracer)},
          {"planet version", id.planet},
          {"model", id.model},
          {"view (camera, sun)", id.view}};
}

}  // namespace

MergedReference merge_reference_shares(const std::vector<std::filesystem::path>& inputs) {
  if (inputs.empty()) throw InputError("--merge: name the folders (or files) of the shares");
  const auto shares = read_shares<ReferenceShareFile>(inputs, share_files, read_reference_share);
  // One render: every share agrees with the most of them ...
  std::vector<ShareOf> of;
  for (const ReferenceShareFile& s : shares)
    of.push_back({s.file, s.id.share, shared_fields(s.id)});
  require_one_job(of);
  // ... and is what this program renders for that scene.
  MergedReference merged;
  const ReferenceShareId& first = shares.front().id;
  merged.scene = find_scene(first.scene);
  merged.scene.width = first.width;
  merged.scene.height = first.height;
  merged.scene.max_order = first.max_order;
  merged.mode = parse_reference_mode(first.mode);
  merged.paths = PathBudget::parse(first.paths);
  ReferenceShareId ours = reference_share_id(merged.scene, merged.paths, merged.mode, Share{});
  for (const ReferenceShareFile& s : shares) {
    auto theirs = program_fields(s.id), mine = program_fields(ours);
    for (size_t f = 0; f < theirs.size(); ++f) {
      if (theirs[f].second != mine[f].second) {
        throw InputError(fmt::format(
            "{}: share {} is of {} {}, this program's for {} is {}: render the share again "
            "with this program",
            s.file.string(), s.id.share.label(), theirs[f].first, theirs[f].second, first.scene,
            mine[f].second));
      }
    }
  }
  // Shares 0 to N-1, each once and finished.
  const int count = first.share.count;
  std::vector<const ReferenceShareFile*> by_index;
  for (const ShareOf* s : shares_by_index(of, first.scene, inputs)) {
    by_index.push_back(&shares[size_t(s - of.data())]);
  }
  Medium medium =
      make_medium(scene_atmosphere(merged.scene, scene_body(merged.scene)), merged.mode);
  const std::vector<int> lane_paths = merged.paths.lane_paths(medium.channels.size());
  for (const ReferenceShareFile* s : by_index) {
    if (s->sums.done != lane_paths) {
      double all = 0, done = 0;
      for (size_t lane = 0; lane < lane_paths.size(); ++lane) {
        all += lane_paths[lane];
        done += lane < s->sums.done.size() ? s->sums.done[lane] : 0;
      }
      throw InputError(
          fmt::format("{}: share {} is unfinished ({:.1f}% of its paths): run it "
                      "again to finish it",
                      s->file.string(), s->id.share.label(), 100.0 * done / all));
    }
  }
  // Every pixel's sums from the share that traced it.
  merged.shares = count;
  merged.sums = by_index.front()->sums;
  const size_t lanes = lane_paths.size();
  const size_t pixels = size_t(first.width) * size_t(first.height);
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    const RenderSums& from = by_index[pixel % size_t(count)]->sums;
    std::copy_n(&from.sum[pixel * lanes], lanes, &merged.sums.sum[pixel * lanes]);
  }
  ReferenceImage image;
  resolve_sums(medium, merged.sums, image);
  merged.render.image = to_image_rgb(image);
  merged.render.noise = {image.width, image.height, image.noise};
  return merged;
}

std::filesystem::path cache_merged_reference(const MergedReference& merged) {
  AtmosphereModel model = scene_atmosphere(merged.scene, scene_body(merged.scene));
  std::filesystem::path file = reference_cache_file(merged.scene, model, merged.paths, merged.mode);
  std::filesystem::create_directories(file.parent_path());
  write_sums(reference_sums_file(file), reference_view_key(merged.scene, model, merged.mode),
             merged.sums);
  // The noise first: a reference in the cache always has its noise.
  write_exr(reference_noise_file(file), merged.render.noise);
  write_exr(file, merged.render.image);
  return file;
}

}  // namespace planet
