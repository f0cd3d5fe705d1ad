#include "atmosphere/reference/path_budget.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>

namespace planet {

PathBudget::PathBudget(std::vector<int> counts) : spp(0), per_channel(std::move(counts)) {
  for (int n : per_channel) spp += n;
}

PathBudget PathBudget::parse(const std::string& text) {
  std::vector<int> counts;
  size_t at = 0;
  while (true) {
    size_t comma = text.find(',', at);
    std::string part = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    // Digits only: stoll alone would take " 5" and "+5" as well.
    auto digit = [](char ch) { return ch >= '0' && ch <= '9'; };
    bool digits = !part.empty() && part.size() <= 9 && std::all_of(part.begin(), part.end(), digit);
    long long n = digits ? std::stoll(part) : -1;
    if (n < 1 || n > (1 << 24)) {
      throw InputError(fmt::format(
          "'{}' is not a path count: give paths per pixel, 1 to {}, in all (98304) or per "
          "channel (32768,131072,524288)",
          text, 1 << 24));
    }
    counts.push_back(int(n));
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return counts.size() == 1 ? PathBudget(counts[0]) : PathBudget(std::move(counts));
}

std::string PathBudget::label() const {
  if (per_channel.empty()) return std::to_string(spp);
  std::string out;
  for (int n : per_channel) out += (out.empty() ? "" : ",") + std::to_string(n);
  return out;
}

std::vector<int> PathBudget::lane_paths(size_t channels) const {
  const size_t lanes = kReplicates * channels;
  std::vector<int> out(lanes);
  if (per_channel.empty()) {
    if (spp < int(lanes)) {
      throw InputError(
          fmt::format("{} samples per pixel: at least {} are needed (one per "
                      "channel in each of {} replicates)",
                      spp, lanes, kReplicates));
    }
    // Path s of the pixel belongs to lane s % lanes.
    for (size_t lane = 0; lane < lanes; ++lane) {
      out[lane] = int((size_t(spp) - lane + lanes - 1) / lanes);
    }
    return out;
  }
  if (per_channel.size() != channels) {
    throw InputError(fmt::format("{} path counts for {} channels: give one per channel",
                                 per_channel.size(), channels));
  }
  for (size_t c = 0; c < channels; ++c) {
    if (per_channel[c] < kReplicates) {
      throw InputError(
          fmt::format("{} paths in channel {}: at least {} are needed (one in each "
                      "replicate)",
                      per_channel[c], c, kReplicates));
    }
    for (size_t r = 0; r < size_t(kReplicates); ++r) {
      out[r * channels + c] = int((size_t(per_channel[c]) - r + kReplicates - 1) / kReplicates);
    }
  }
  return out;
}

}  // namespace planet
