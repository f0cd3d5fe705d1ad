#include "render/technique_switch.h"

#include "atmosphere/gpu/registry.h"

#include <algorithm>

namespace planet {

namespace {

// Techniques kept aside with their tables: a few hundred MB at most.
constexpr size_t kKeptAside = 4;

}  // namespace

TechniqueSwitch::TechniqueSwitch(FrameRenderer& renderer, std::string current)
    : renderer_(renderer), current_(renderer.technique() ? std::move(current) : std::string()) {}

AtmosphereTechnique* TechniqueSwitch::kept(const std::string& choice,
                                           const AtmosphereModel& model) {
  auto it = kept_.find(choice);
  if (it == kept_.end()) return nullptr;
  if (stale_.erase(choice)) it->second->update(model);
  order_.erase(std::remove(order_.begin(), order_.end(), choice), order_.end());
  order_.push_back(choice);
  return it->second.get();
}

void TechniqueSwitch::apply(const GovernorDecision& decision, const AtmosphereModel& model) {
  if (decision.choice != current_) {
    std::unique_ptr<AtmosphereTechnique> next;
    if (kept(decision.choice, model)) {
      next = std::move(kept_[decision.choice]);
      kept_.erase(decision.choice);
      order_.erase(std::remove(order_.begin(), order_.end(), decision.choice), order_.end());
    } else {
      next = make_technique(decision.choice);
      next->update(model);
    }
    std::unique_ptr<AtmosphereTechnique> previous = renderer_.swap_technique(std::move(next));
    if (previous && !current_.empty()) {
      kept_[current_] = std::move(previous);
      order_.push_back(current_);
    }
    current_ = decision.choice;
    while (kept_.size() > kKeptAside) {
      // Never the one a fade still draws.
      auto victim = std::find_if(order_.begin(), order_.end(), [&](const std::string& c) {
        return c != decision.fading_from;
      });
      if (victim == order_.end()) break;
      kept_.erase(*victim);
      stale_.erase(*victim);
      order_.erase(victim);
    }
  }
  AtmosphereTechnique* fading = nullptr;
  if (!decision.fading_from.empty() && decision.fading_from != current_) {
    fading = kept(decision.fading_from, model);
    if (!fading) {
      // A capture's slice that starts within a fade: the technique faded
      // from never drew here, and is built now.
      auto t = make_technique(decision.fading_from);
      t->update(model);
      fading = t.get();
      kept_[decision.fading_from] = std::move(t);
      order_.push_back(decision.fading_from);
    }
  }
  renderer_.set_fade(fading, fading ? decision.fade_weight : 0.0);
}

void TechniqueSwitch::model_changed() {
  for (const auto& [choice, technique] : kept_) stale_.insert(choice);
}

}  // namespace planet
