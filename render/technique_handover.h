#pragma once
// A technique chosen by hand in a window (fly's T) built between frames
// while the one before draws on, then faded in: the window never stops for
// a technique's tables (bruneton's take a minute on llvmpipe the first
// time). The governor's switches (technique_switch.h) build theirs at once:
// a capture must not change with the machine's speed.
#include "atmosphere/gpu/technique.h"
#include "render/frame.h"

#include <memory>
#include <string>

namespace planet {

class TechniqueHandover {
 public:
  // How long the old technique fades out once the new one is built.
  static constexpr double kFadeSeconds = 1.0;

  // Builds `choice` for `model`; the renderer's technique draws meanwhile.
  // Nothing is built before the first advance().
  TechniqueHandover(FrameRenderer& renderer, std::string choice, AtmosphereModel model);
  // Ends a fade at once (the new technique draws alone); a build not
  // finished is dropped and the renderer keeps its technique.
  ~TechniqueHandover();
  TechniqueHandover(const TechniqueHandover&) = delete;
  TechniqueHandover& operator=(const TechniqueHandover&) = delete;

  // Between two frames, `real_dt` after the last: builds for `seconds` (at
  // least one slice), and once built swaps the new technique into the
  // renderer and fades the old one out over kFadeSeconds. True when it
  // swapped this call.
  bool advance(double real_dt, double seconds);
  // The swap has happened; the fade may still run.
  bool built() const { return built_; }
  // Built and faded: nothing is left to do.
  bool finished() const { return built_ && fade_left_ <= 0.0; }
  const std::string& choice() const { return choice_; }
  // The build's fraction done (0 to 1) and a line for the HUD ("building
  // bruneton 37 %: order 2 of 4", "fading to bruneton").
  double fraction() const;
  std::string status() const;
  // Of the build: its wall time, the part of it spent building (the rest
  // drew frames), the frames drawn while it ran and the longest time
  // between two of them (the build's slices included).
  double wall_seconds() const { return wall_seconds_; }
  double build_seconds() const { return build_seconds_; }
  int frames_while_building() const { return frames_; }
  double longest_frame_seconds() const { return longest_frame_; }

 private:
  FrameRenderer& renderer_;
  std::string choice_;
  AtmosphereModel model_;
  std::unique_ptr<AtmosphereTechnique> next_, previous_;
  std::unique_ptr<TableBuild> build_;
  bool built_ = false;
  double fade_left_ = 0;
  double wall_seconds_ = 0, build_seconds_ = 0, longest_frame_ = 0;
  int frames_ = 0;
};

}  // namespace planet
