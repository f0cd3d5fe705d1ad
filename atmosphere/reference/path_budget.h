#pragma once
// How many paths a reference render traces, and how they are spread over
// its replicates and channels (lanes).
#include <string>
#include <vector>

namespace planet {

// A render is the mean of two independent replicates (each its own
// scrambling of the stratified sequences), and half their difference is
// the standard error of that mean: its square's expectation is the mean's
// variance. Stratified sampling makes the spread of the paths themselves
// overstate the error, so the replicates are what measures it.
constexpr int kReplicates = 2;

// Paths per pixel: `spp` in all, spread evenly over the replicates and the
// channels; or, where `per_channel` is given, that many in each channel
// (spread over the replicates). A channel's noise falls as one over the
// square root of its paths, and the channels are traced apart, so the
// noisiest one (Earth's blue) can have more without the others paying.
struct PathBudget {
  int spp = 64;
  std::vector<int> per_channel;

  PathBudget() = default;
  PathBudget(int count) : spp(count) {}  // NOLINT: a plain count reads as one
  explicit PathBudget(std::vector<int> counts);
  // "98304" (in all) or "32768,131072,524288" (per channel); InputError
  // for anything else or a count below 1 or above 2^24.
  static PathBudget parse(const std::string& text);
  // The form parse() reads: for file names and messages.
  std::string label() const;
  // Paths per pixel in each lane, lane = replicate * channels + channel;
  // InputError where a lane would get none.
  std::vector<int> lane_paths(size_t channels) const;
  bool operator==(const PathBudget&) const = default;
};

}  // namespace planet
