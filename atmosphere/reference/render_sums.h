#pragma once
// The checkpoints of a reference render: its running sums, and the file
// they are kept in between runs.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace planet {

// The running sums of a render, which make it one that can stop and go
// on: per pixel and lane, the sum of the radiance of the lane's paths
// [0, done[lane]). A path's numbers depend only on its pixel, lane and
// index, and a pixel's sums add its paths in index order, so a render that
// goes on from sums it wrote part-way, or from the sums of a smaller
// budget, ends with the same bits as one that never stopped.
struct RenderSums {
  int width = 0, height = 0;
  std::vector<int> done;    // paths traced so far, per lane
  std::vector<double> sum;  // [pixel * lanes + lane]

  // Paths traced so far per pixel, all lanes together.
  int64_t traced() const;
  // Whether a render with these paths per lane can go on from here: as
  // many lanes, and no more paths in any of them.
  bool fits(const std::vector<int>& lane_paths) const;
};

// The sums as a file: a text header (magic, `view_key`, width height
// lanes, paths per lane), then the sums as little-endian doubles. Written
// whole or not at all (core/atomic_file.h): a render killed while writing
// leaves the last whole checkpoint.
void write_sums(const std::filesystem::path& file, const std::string& view_key,
                const RenderSums& sums);
// The sums in `file`, or nothing where they are of another view (their
// key is not `view_key`). A file that is not sums at all is an InputError
// that names it.
std::optional<RenderSums> read_sums(const std::filesystem::path& file, const std::string& view_key);

}  // namespace planet
