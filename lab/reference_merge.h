#pragma once
// The shares of a reference render put together (`planet reference --merge
// DIR...`): the same image and noise, bit for bit, as the render made at
// once, or one InputError naming the share that does not belong.
#include "lab/reference_cache.h"
#include "lab/reference_share.h"

#include <filesystem>
#include <vector>

namespace planet {

struct MergedReference {
  Scene scene;
  PathBudget paths;
  ReferenceMode mode = ReferenceMode::kRgb;
  int shares = 0;
  ReferenceRender render;  // image and noise
  RenderSums sums;         // of every pixel
};

// Reads every share in `inputs` (share files, or folders holding
// share-K-of-N.sums) and checks, before putting anything together, that
// they are one render's shares 0 to N-1, each once and finished, of one
// scene, size, mode, path budget, model, tracer and program version (the
// ones this program would render). InputError otherwise, naming the share
// and what differs.
MergedReference merge_reference_shares(const std::vector<std::filesystem::path>& inputs);

// Keeps a merged reference in the cache (reference_cache.h) with its noise
// and sums, as if rendered here: `planet accuracy` then finds it, and a
// larger budget goes on from its sums.
std::filesystem::path cache_merged_reference(const MergedReference& merged);

}  // namespace planet
