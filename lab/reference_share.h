#pragma once
// One share of a reference render for a cluster: `planet reference --shard
// K/N` traces every path of the pixels whose index % N == K and keeps their
// running sums in a file that says what they are of. Each pixel's sums add
// its paths in index order whoever traces them, so shares put together
// (reference_merge.h) give the bits of the render made at once.
#include "atmosphere/reference/path_budget.h"
#include "atmosphere/reference/render_sums.h"
#include "core/share.h"
#include "lab/scene.h"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace planet {

// What a share is of: everything that changes its sums, each named apart
// so that a merge can say which one differs.
struct ReferenceShareId {
  std::string scene;
  int width = 0, height = 0;
  std::string mode;    // to_string(ReferenceMode)
  int max_order = 0;   // Scene::max_order: 0 every order
  std::string paths;   // PathBudget::label()
  std::string model;   // reference_model_key: the model as loaded
  std::string view;    // reference_view_key: camera, sun, size and model
  int tracer = 0;      // kReferenceVersion
  std::string planet;  // planet_version()
  Share share;
};

ReferenceShareId reference_share_id(const Scene& scene, const PathBudget& paths, ReferenceMode mode,
                                    const Share& share);

// Where the shares of the reference written to `out` (an EXR) go: beside
// it, in `<out's stem>.shares/share-K-of-N.sums`.
std::filesystem::path reference_shares_dir(const std::filesystem::path& out);
std::filesystem::path reference_share_file(const std::filesystem::path& shares_dir,
                                           const Share& share);
// Where a share keeps its checkpoints until it is finished
// (share-K-of-N.part): a share-K-of-N.sums is always a finished share.
std::filesystem::path reference_share_checkpoint(const std::filesystem::path& share_file);

// A share as a file: a text header of "key value" lines (ReferenceShareId,
// then `lanes` and `done`, the paths per lane so far), then the sums of
// the share's pixels in index order, `lanes` little-endian doubles each.
// Written whole or not at all.
void write_reference_share(const std::filesystem::path& file, const ReferenceShareId& id,
                           const RenderSums& sums);
struct ReferenceShareFile {
  std::filesystem::path file;
  ReferenceShareId id;
  RenderSums sums;  // the whole image's size; pixels of other shares hold 0
};
// InputError naming the file where it is not a share of a reference.
ReferenceShareFile read_reference_share(const std::filesystem::path& file);

struct ReferenceShareRender {
  std::filesystem::path file;
  uint64_t paths = 0;        // traced by this run
  double started_share = 0;  // of its paths, found done in the file already
};

// Renders share `share` of the reference into reference_share_file(
// reference_shares_dir(out), share), checkpointing beside it as it goes: a
// share run again goes on from its checkpoint (and a finished one is
// rewritten as it was). `cancel` stops it with ReferenceInterrupted.
ReferenceShareRender render_reference_share(const Scene& scene, const PathBudget& paths,
                                            ReferenceMode mode, const Share& share,
                                            const std::filesystem::path& out,
                                            const std::function<void(double)>& progress = {},
                                            const std::atomic<bool>* cancel = nullptr);

}  // namespace planet
