#pragma once
// A capture split over a cluster: share K of N renders a contiguous run of
// the flight's frames (core/share.h, share_range) into its own folder, a
// capture of its own with its capture.json; the merge puts the shares'
// frames into one capture folder. Frames do not depend on the frames
// rendered before them, so the merged folder's images are the bytes of one
// run's.
#include "core/share.h"
#include "render/capture_folder.h"
#include "sim/flight_script.h"

#include <filesystem>
#include <vector>

namespace planet {

// `<out>.shares`, beside the capture folder `out`, and share K of N's
// folder in it, `share-K-of-N`.
std::filesystem::path capture_shares_dir(const std::filesystem::path& out);
std::filesystem::path capture_share_dir(const std::filesystem::path& shares_dir,
                                        const Share& share);

// The frames [first, end) of share K of N of the script; InputError where
// there are more shares than frames.
std::pair<int, int> capture_share_frames(const FlightScript& script, const Share& share);

struct MergedCapture {
  int frames = 0;
  int shares = 0;
  double wall_seconds = 0;  // the shares' together
  FramesBeyond removed;     // of an earlier, longer capture into `out`
};

// Checks that `inputs` (share folders, or folders holding share-K-of-N
// folders) are shares 0 to N-1 of one capture, each once, finished (its
// capture.json), of one flight script's text, size, rate, technique and
// program version, with every frame's files; then copies their frames
// into `out` and writes its capture.json last: a run at once's, but for
// its wall time, the shares' together. Nothing is written where a check
// fails: InputError naming the share and what is wrong. Frames in `out`
// beyond the flight's last, an earlier and longer capture's, are removed
// as a run at once removes them (the merge overwrites that capture's other
// frames anyway).
MergedCapture merge_capture_shares(const std::vector<std::filesystem::path>& inputs,
                                   const std::filesystem::path& out);

}  // namespace planet
