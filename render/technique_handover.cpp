#include "render/technique_handover.h"

#include "atmosphere/gpu/registry.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace planet {

TechniqueHandover::TechniqueHandover(FrameRenderer& renderer, std::string choice,
                                     AtmosphereModel model)
    : renderer_(renderer), choice_(std::move(choice)), model_(std::move(model)) {}

TechniqueHandover::~TechniqueHandover() {
  if (previous_) renderer_.set_fade(nullptr, 0.0);
}

bool TechniqueHandover::advance(double real_dt, double seconds) {
  if (built_) {
    fade_left_ -= real_dt;
    if (fade_left_ > 0.0) {
      renderer_.set_fade(previous_.get(), fade_left_ / kFadeSeconds);
    } else {
      renderer_.set_fade(nullptr, 0.0);
      previous_.reset();
    }
    return false;
  }
  // The interval before the first call came before the build.
  if (next_) {
    ++frames_;
    longest_frame_ = std::max(longest_frame_, real_dt);
    wall_seconds_ += real_dt;
  }
  const auto began = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  };
  bool done = false;
  do {
    // The technique's own programs are its first slice.
    if (!next_) {
      next_ = make_technique(choice_);
    } else if (!build_) {
      build_ = next_->update_in_slices(model_);
    } else {
      done = build_->step();
    }
  } while (!done && elapsed() < seconds);
  build_seconds_ += elapsed();
  if (!done) return false;
  // The interval from the last frame to this swap.
  wall_seconds_ += elapsed();
  build_.reset();
  previous_ = renderer_.swap_technique(std::move(next_));
  built_ = true;
  fade_left_ = previous_ ? kFadeSeconds : 0.0;
  renderer_.set_fade(previous_.get(), 1.0);
  return true;
}

double TechniqueHandover::fraction() const {
  if (built_) return 1.0;
  return build_ ? build_->fraction() : 0.0;
}

std::string TechniqueHandover::status() const {
  if (built_) return fmt::format("fading to {}", choice_);
  if (!build_) return fmt::format("building {} 0 %: its programs", choice_);
  return fmt::format("building {} {:.0f} %: {}", choice_, std::floor(100.0 * fraction()),
                     build_->what());
}

}  // namespace planet
