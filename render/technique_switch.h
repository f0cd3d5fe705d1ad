#pragma once
// The governor's choices drawn (governor/governor.h): each technique it has
// used is kept with its tables, so that switching back costs nothing, and
// the renderer gets the chosen one and, while a switch fades, the one
// before it.
#include "governor/governor.h"
#include "render/frame.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace planet {

class TechniqueSwitch {
 public:
  // The renderer draws a body with an atmosphere; its technique, if any,
  // is taken to be `current`.
  TechniqueSwitch(FrameRenderer& renderer, std::string current);

  // The decision's choice becomes the renderer's technique (built and given
  // `model` the first time), and the choice it fades from its fade.
  void apply(const GovernorDecision& decision, const AtmosphereModel& model);
  // The renderer's model changed (FrameRenderer::set_atmosphere): the
  // techniques kept aside take it when they are next used.
  void model_changed();

  const std::string& current() const { return current_; }

 private:
  AtmosphereTechnique* kept(const std::string& choice, const AtmosphereModel& model);

  FrameRenderer& renderer_;
  std::string current_;
  std::map<std::string, std::unique_ptr<AtmosphereTechnique>> kept_;
  std::vector<std::string> order_;  // kept_, the longest unused first
  std::set<std::string> stale_;
};

}  // namespace planet
