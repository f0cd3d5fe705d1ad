#pragma once
// The governor's table (governor/governor.h) from the lab's sweep: one row
// per canonical scene, described as the governor describes a view, with
// each (technique, quality)'s measured error and cost there; and what a
// change of model recomputes for each, measured once per choice.
#include "governor/governor.h"
#include "lab/gpu/sweep.h"

#include <functional>
#include <map>
#include <string>

namespace planet {

// "hillaire:cheap", or "hillaire" for the default: how the table and the
// governor name a quality point (parse_technique reads both).
std::string governor_choice(const std::string& technique, const std::string& quality);

// Wall ms of what a change of model recomputes for `choice` on `scene`'s
// view: the technique's update to a model it has not seen (no disk cache)
// and the first frame after it, less a frame with the model unchanged.
// Needs a GL context.
double measure_model_change_ms(const Scene& scene, const std::string& choice);

// The plan's choices' model changes on its first scene, each measured once
// and kept in OUT/model_change.json (a sweep run again measures only those
// missing; --redo all of them). `progress` sees the choice now measured.
std::map<std::string, double> model_change_times(const SweepOptions& options,
                                                 const SweepPlan& plan,
                                                 const std::function<void(const std::string&)>& progress);

// The table: every scene of the cells, each cell an entry.
ErrorModel build_error_model(const std::vector<SweepCell>& cells,
                             const std::map<std::string, double>& model_change_ms,
                             const SweepOptions& options, const std::string& source);

}  // namespace planet
