// planet techniques: every atmosphere technique with its quality
// parameters, their ranges and defaults (atmosphere/gpu/registry.h).
#include "apps/commands.h"
#include "atmosphere/gpu/registry.h"

#include <cstdio>

namespace planet::apps {

void add_techniques_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("techniques",
                                     "List the atmosphere techniques and their quality parameters");
  cmd->callback([] { std::fputs(describe_techniques().c_str(), stdout); });
}

}  // namespace planet::apps
