#pragma once
// One share of a deterministic job split over many machines: share K of N
// ("--shard K/N", K from 0 as a scheduler's array index counts). Each share
// does a fixed part of the work, known from K and N alone, so shares can
// run in any order, anywhere, and again.
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace planet {

struct Share {
  int index = 0;  // K, 0 <= K < N
  int count = 1;  // N
  bool whole() const { return count == 1; }
  // "2/4"
  std::string label() const;
  bool operator==(const Share&) const = default;
};

// "K/N" with 0 <= K < N <= 65536; InputError naming `what` ("--shard")
// and the text otherwise.
Share parse_share(const std::string& text, const std::string& what);

// The share's run of `total` items [first, end), contiguous and as even as
// can be: shares 0..N-1 cover 0..total once, in order. Some are empty
// where N > total.
std::pair<int, int> share_range(const Share& share, int total);

// The entries of `folder` named share-... that `wanted` takes (a share's
// file, or its folder), in name order: what a merge reads. InputError
// "--merge FOLDER: holds no shares (HINT)" where there are none; `hint`
// says what a share looks like and what writes it.
std::vector<std::filesystem::path> share_entries(
    const std::filesystem::path& folder,
    const std::function<bool(const std::filesystem::directory_entry&)>& wanted,
    const std::string& hint);

// InputError naming the shares 0..N-1 that `present` lacks ("shares 1/4,
// 3/4 of WHAT are missing from INPUTS (2 of 4 found)"); nothing where it
// lacks none.
void require_every_share(const std::vector<bool>& present, const std::string& what,
                         const std::vector<std::filesystem::path>& inputs);

}  // namespace planet
