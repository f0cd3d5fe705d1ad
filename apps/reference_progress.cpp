#include "apps/reference_progress.h"

#include "core/interrupt.h"
#include "core/progress.h"

#include <cstdio>
#include <cstdlib>

namespace planet::apps {

ReferenceRender reference_for_command(const Scene& scene, const PathBudget& budget, bool quiet) {
  if (!reference_cached(scene, budget, ReferenceMode::kRgb) && !quiet) {
    RenderCost cost = estimate_reference_cost(scene, budget, ReferenceMode::kRgb);
    std::fprintf(stderr, "planet: %s\n",
                 describe_uncached_reference(scene, budget, ReferenceMode::kRgb, cost).c_str());
  }
  double paths = double(scene.width) * scene.height * budget.spp;
  Progress progress("reference " + scene.name, paths, "path", quiet);
  bool first = true;
  auto on_progress = [&](double done) {
    if (first) progress.begin_at(done * paths);  // what it goes on from
    first = false;
    progress.update(done * paths);
  };
  try {
    ReferenceRender render = reference_render(scene, budget, ReferenceMode::kRgb, on_progress,
                                              &InterruptScope::flag());
    progress.finish();
    return render;
  } catch (const ReferenceInterrupted& e) {
    progress.finish();
    std::fprintf(stderr, "planet: %s\n", e.what());
    std::exit(kInterruptedExitStatus);
  }
}

}  // namespace planet::apps
