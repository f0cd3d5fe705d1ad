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

// Every share that `inputs` name, in their order: an input's entries (the
// input itself, or the shares in a folder: share_entries) each `read`.
template <class T, class Entries, class Read>
std::vector<T> read_shares(const std::vector<std::filesystem::path>& inputs, Entries entries,
                           Read read) {
  std::vector<T> shares;
  for (const std::filesystem::path& input : inputs) {
    for (const std::filesystem::path& entry : entries(input)) shares.push_back(read(entry));
  }
  return shares;
}

// One share as a merge reads it: where it is, which it is, and what the
// shares of one job agree on, as (name, value) in the same order for each.
struct ShareOf {
  std::filesystem::path where;
  Share share;
  std::vector<std::pair<std::string, std::string>> fields;
};

// InputError "WHERE: share K/N is of NAME VALUE, the other shares of
// VALUE" for the first share that differs from what most of them hold: the
// odd one out is named, not the others.
void require_one_job(const std::vector<ShareOf>& shares);

// The shares in index order, 0 to N-1 of the count the first holds (agreed
// by require_one_job): InputError "share K/N is given twice: A and B", or
// require_every_share's for those not there.
std::vector<const ShareOf*> shares_by_index(const std::vector<ShareOf>& shares,
                                            const std::string& what,
                                            const std::vector<std::filesystem::path>& inputs);

}  // namespace planet
