#include "lab/reference_share.h"

#include "atmosphere/reference/reference_render.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/version.h"
#include "lab/reference_cache.h"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace planet {

namespace {

constexpr const char* kShareMagic = "planet reference share 1";

}  // namespace

ReferenceShareId reference_share_id(const Scene& scene, const PathBudget& paths, ReferenceMode mode,
                                    const Share& share) {
  AtmosphereModel model = scene_atmosphere(scene, scene_body(scene));
  ReferenceShareId id;
  id.scene = scene.name;
  id.width = scene.width;
  id.height = scene.height;
  id.mode = to_string(mode);
  id.max_order = scene.max_order;
  id.paths = paths.label();
  id.model = reference_model_key(model, mode);
  id.view = reference_view_key(scene, model, mode);
  id.tracer = kReferenceVersion;
  id.planet = planet_version();
  id.share = share;
  return id;
}

std::filesystem::path reference_shares_dir(const std::filesystem::path& out) {
  std::filesystem::path dir = out;
  dir.replace_extension(".shares");
  return dir;
}

std::filesystem::path reference_share_file(const std::filesystem::path& shares_dir,
                                           const Share& share) {
  return shares_dir / fmt::format("share-{}-of-{}.sums", share.index, share.count);
}

std::filesystem::path reference_share_checkpoint(const std::filesystem::path& share_file) {
  return std::filesystem::path(share_file).replace_extension(".part");
}

void write_reference_share(const std::filesystem::path& file, const ReferenceShareId& id,
                           const RenderSums& sums) {
  std::string bytes = fmt::format(
      "{}\nscene {}\nsize {}x{}\nmode {}\norders {}\npaths {}\nmodel {}\nview {}\ntracer {}\n"
      "planet {}\nshare {}\nlanes {}\ndone",
      kShareMagic, id.scene, id.width, id.height, id.mode,
      id.max_order > 0 ? std::to_string(id.max_order) : "all", id.paths, id.model, id.view,
      id.tracer, id.planet, id.share.label(), sums.done.size());
  for (int n : sums.done) bytes += fmt::format(" {}", n);
  bytes += "\n";
  const size_t lanes = sums.done.size();
  const size_t pixels = size_t(sums.width) * size_t(sums.height);
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    if (!share_owns_pixel(id.share, pixel)) continue;
    bytes.append(reinterpret_cast<const char*>(&sums.sum[pixel * lanes]), lanes * sizeof(double));
  }
  write_file_atomically(file, bytes);
}

ReferenceShareFile read_reference_share(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  auto bad = [&](const std::string& what) {
    return InputError(fmt::format("{}: {}", file.string(), what));
  };
  if (!in) throw bad("cannot be read");
  std::string line;
  std::getline(in, line);
  if (line != kShareMagic) throw bad("not a share of a reference (planet reference --shard)");
  ReferenceShareFile out;
  out.file = file;
  ReferenceShareId& id = out.id;
  // The header's lines in their order: a missing or misspelt one is named.
  auto field = [&](const char* key) {
    std::getline(in, line);
    std::string prefix = std::string(key) + " ";
    if (!in || line.rfind(prefix, 0) != 0) {
      throw bad(fmt::format("its header has no '{}' line where expected", key));
    }
    return line.substr(prefix.size());
  };
  id.scene = field("scene");
  std::string size = field("size");
  if (std::sscanf(size.c_str(), "%dx%d", &id.width, &id.height) != 2 || id.width < 1 ||
      id.height < 1 || id.width > 8192 || id.height > 8192) {
    throw bad(fmt::format("its size '{}' is not WIDTHxHEIGHT", size));
  }
  id.mode = field("mode");
  std::string orders = field("orders");
  if (orders != "all") {
    try {
      id.max_order = std::stoi(orders);
    } catch (const std::exception&) {
      id.max_order = -1;
    }
    if (id.max_order < 1 || std::to_string(id.max_order) != orders) {
      throw bad(fmt::format("its orders '{}' are neither 'all' nor a count from 1", orders));
    }
  }
  id.paths = field("paths");
  id.model = field("model");
  id.view = field("view");
  std::string tracer = field("tracer");
  try {
    id.tracer = std::stoi(tracer);
  } catch (const std::exception&) {
    throw bad(fmt::format("its tracer version '{}' is not a number", tracer));
  }
  id.planet = field("planet");
  id.share = parse_share(field("share"), file.string() + ": share");
  std::istringstream lanes_line(field("lanes"));
  size_t lanes = 0;
  if (!(lanes_line >> lanes) || lanes < 1 || lanes > 1024)
    throw bad("its lane count is not 1 to 1024");
  std::istringstream done_line(" " + field("done"));
  RenderSums& sums = out.sums;
  sums.width = id.width;
  sums.height = id.height;
  sums.done.resize(lanes);
  for (int& n : sums.done) {
    if (!(done_line >> n) || n < 0) throw bad("its 'done' line does not give one count per lane");
  }
  const size_t pixels = size_t(id.width) * size_t(id.height);
  sums.sum.assign(pixels * lanes, 0.0);
  size_t owned = 0;
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    if (!share_owns_pixel(id.share, pixel)) continue;
    in.read(reinterpret_cast<char*>(&sums.sum[pixel * lanes]),
            std::streamsize(lanes * sizeof(double)));
    ++owned;
  }
  if (!in || in.peek() != std::char_traits<char>::eof()) {
    throw bad(fmt::format("it should hold the sums of {} pixels after its header", owned));
  }
  return out;
}

ReferenceShareRender render_reference_share(const Scene& scene, const PathBudget& paths,
                                            ReferenceMode mode, const Share& share,
                                            const std::filesystem::path& out,
                                            const std::function<void(double)>& progress,
                                            const std::atomic<bool>* cancel) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  Medium medium = make_medium(model, mode);
  const std::vector<int> lane_paths = paths.lane_paths(medium.channels.size());
  const ReferenceShareId id = reference_share_id(scene, paths, mode, share);
  const std::filesystem::path dir = reference_shares_dir(out);
  std::filesystem::create_directories(dir);
  ReferenceShareRender result;
  result.file = reference_share_file(dir, share);

  ReferenceSettings settings = reference_settings(scene, paths);
  settings.share = share;
  settings.progress = progress;
  settings.cancel = cancel;
  const std::filesystem::path checkpoint = reference_share_checkpoint(result.file);
  bool checkpointed = false;
  settings.checkpoint = [&](const RenderSums& sums) {
    write_reference_share(checkpoint, id, sums);
    checkpointed = true;
  };
  // A share run again goes on from where it got to (or, finished, is
  // written again as it was), where that is of the same share of the same
  // render; anything else there is replaced.
  RenderSums start;
  for (const std::filesystem::path& file : {result.file, checkpoint}) {
    if (settings.start || !std::filesystem::exists(file)) continue;
    try {
      ReferenceShareFile found = read_reference_share(file);
      if (found.id.view == id.view && found.id.paths == id.paths && found.id.tracer == id.tracer &&
          found.id.planet == id.planet && found.id.share == id.share &&
          found.sums.fits(lane_paths)) {
        start = std::move(found.sums);
        settings.start = &start;
        double all = 0;
        for (int n : lane_paths) all += n;
        result.started_share = double(start.traced()) / all;
      }
    } catch (const InputError&) {
      // Not a share this render can go on from: rendered again from nothing.
    }
  }
  ReferenceImage image;
  try {
    image = render_reference(medium, reference_view(scene, body, model), settings);
  } catch (const RenderInterrupted& e) {
    throw ReferenceInterrupted(fmt::format(
        "interrupted: {:.1f}% of the paths of share {} of {} are kept in {}; run the same "
        "command again to go on",
        100.0 * e.kept_share, share.label(), scene.name, checkpoint.string()));
  }
  // The last checkpoint holds every path (none was written where the
  // render started finished): it becomes the share.
  if (!checkpointed) write_reference_share(checkpoint, id, start);
  std::filesystem::rename(checkpoint, result.file);
  result.paths = image.paths;
  return result;
}

}  // namespace planet
