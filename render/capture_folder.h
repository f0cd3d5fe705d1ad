#pragma once
// What a capture folder holds: each frame as frame_NNNNN.exr, .png and
// .json (whole once its sidecar is there, render/capture.h) and, written
// last, capture.json. One run fills a folder, or several: slices one after
// another, a run that resumes an interrupted one, the merge of a capture's
// shares. capture.json describes the frames the folder holds, whichever
// runs made them.
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <functional>
#include <string>

namespace planet {

// "frame_00042": the name of frame 42's files, less their extension.
std::string frame_stem(int frame);

// Removes the images of the frames [first, end) that have no sidecar: a
// frame is published as its images and then its sidecar, and a run killed
// between them leaves the images of a frame that is not one. Other frames
// are left to whoever writes them (a slice running beside this one into
// the same folder).
void remove_frames_without_sidecar(const std::filesystem::path& dir, int first, int end);

// The frames of a folder numbered `total` or more, which a flight of
// `total` frames never writes: an earlier, longer capture's.
struct FramesBeyond {
  int count = 0;
  int first = -1, last = -1;  // the lowest and highest of them
};
// Removes their files (EXR, PNG and sidecar; nothing else of the folder).
FramesBeyond remove_frames_beyond(const std::filesystem::path& dir, int total);

// The whole frames a folder holds of one capture, around the frames
// [run_first, run_end) a run has just written: the longest run of frames
// [first, end) within [lowest, highest) that holds it, each with its
// sidecar, each sidecar of this capture (`of_capture(frame, sidecar)`);
// and the seconds they took, the sum of their sidecars' "wall_seconds".
struct FolderFrames {
  int first = 0, end = 0;
  double wall_seconds = 0;
};
FolderFrames whole_frames_around(
    const std::filesystem::path& dir, int run_first, int run_end, int lowest, int highest,
    const std::function<bool(int frame, const nlohmann::json& sidecar)>& of_capture);

}  // namespace planet
