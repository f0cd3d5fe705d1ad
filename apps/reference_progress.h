#pragma once
// A canonical scene's ground truth for a command that needs it (accuracy,
// lab run): read from the cache, or rendered after a line that says what
// it will cost, with its progress. Ctrl-C keeps what is done, says how to go
// on, and ends the program with 130. Needs an InterruptScope alive.
#include "lab/reference_cache.h"

namespace planet::apps {

ReferenceRender reference_for_command(const Scene& scene, const PathBudget& budget, bool quiet);

}  // namespace planet::apps
