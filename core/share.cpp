#include "core/share.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <map>

namespace planet {

std::string Share::label() const { return fmt::format("{}/{}", index, count); }

Share parse_share(const std::string& text, const std::string& what) {
  auto digits = [](const std::string& s) {
    return !s.empty() && s.size() <= 6 &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  size_t slash = text.find('/');
  std::string k = slash == std::string::npos ? text : text.substr(0, slash);
  std::string n = slash == std::string::npos ? "" : text.substr(slash + 1);
  if (!digits(k) || !digits(n)) {
    throw InputError(fmt::format("{} '{}': expected K/N, share K (from 0) of N", what, text));
  }
  Share share{std::stoi(k), std::stoi(n)};
  if (share.count < 1 || share.count > 65536 || share.index >= share.count) {
    throw InputError(fmt::format("{} '{}': K must be 0 to N-1 and N 1 to 65536", what, text));
  }
  return share;
}

std::pair<int, int> share_range(const Share& share, int total) {
  // 64-bit products: total * N can pass 2^31 for long captures on many tasks.
  auto edge = [&](int k) { return int(int64_t(total) * k / share.count); };
  return {edge(share.index), edge(share.index + 1)};
}

std::vector<std::filesystem::path> share_entries(
    const std::filesystem::path& folder,
    const std::function<bool(const std::filesystem::directory_entry&)>& wanted,
    const std::string& hint) {
  std::vector<std::filesystem::path> entries;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().filename().string().rfind("share-", 0) == 0 && wanted(entry)) {
      entries.push_back(entry.path());
    }
  }
  if (entries.empty()) {
    throw InputError(fmt::format("--merge {}: holds no shares ({})", folder.string(), hint));
  }
  std::sort(entries.begin(), entries.end());
  return entries;
}

void require_every_share(const std::vector<bool>& present, const std::string& what,
                         const std::vector<std::filesystem::path>& inputs) {
  const int count = int(present.size());
  std::string missing;
  int missing_count = 0;
  for (int k = 0; k < count; ++k) {
    if (present[size_t(k)]) continue;
    missing += fmt::format("{}{}/{}", missing.empty() ? "" : ", ", k, count);
    ++missing_count;
  }
  if (missing_count == 0) return;
  std::string where;
  for (const std::filesystem::path& input : inputs) where += " " + input.string();
  throw InputError(fmt::format(
      "share{} {} of {} {} missing from{} ({} of {} found)", missing_count > 1 ? "s" : "", missing,
      what, missing_count > 1 ? "are" : "is", where, count - missing_count, count));
}

void require_one_job(const std::vector<ShareOf>& shares) {
  if (shares.empty()) return;
  for (size_t f = 0; f < shares.front().fields.size(); ++f) {
    std::map<std::string, int> votes;
    std::string best;
    for (const ShareOf& s : shares) {
      const std::string& value = s.fields[f].second;
      if (++votes[value] > votes[best] || best.empty()) best = value;
    }
    for (const ShareOf& s : shares) {
      if (s.fields[f].second != best) {
        throw InputError(fmt::format("{}: share {} is of {} {}, the other shares of {}",
                                     s.where.string(), s.share.label(), s.fields[f].first,
                                     s.fields[f].second, best));
      }
    }
  }
}

std::vector<const ShareOf*> shares_by_index(const std::vector<ShareOf>& shares,
                                            const std::string& what,
                                            const std::vector<std::filesystem::path>& inputs) {
  if (shares.empty()) return {};
  const int count = shares.front().share.count;
  std::vector<const ShareOf*> by_index(size_t(count), nullptr);
  for (const ShareOf& s : shares) {
    if (s.share.count != count) {
      throw InputError(fmt::format("{}: share {} is of share count {}, the other shares of {}",
                                   s.where.string(), s.share.label(), s.share.count, count));
    }
    const ShareOf*& slot = by_index[size_t(s.share.index)];
    if (slot) {
      throw InputError(fmt::format("share {} is given twice: {} and {}", s.share.label(),
                                   slot->where.string(), s.where.string()));
    }
    slot = &s;
  }
  std::vector<bool> present(size_t(count), false);
  for (int k = 0; k < count; ++k) present[size_t(k)] = by_index[size_t(k)] != nullptr;
  require_every_share(present, what, inputs);
  return by_index;
}

}  // namespace planet
