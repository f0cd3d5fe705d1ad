// planet: a thin command line over the modules. Each subcommand registers
// itself (apps/commands.h) and does its work in its callback; every error
// is caught here once and printed as one line.
#include "apps/commands.h"
#include "atmosphere/gpu/registry.h"
#include "core/error.h"

#include <unistd.h>
#include <cstdio>

// One line on stderr; on a terminal, first end any progress line.
static void report(const std::exception& e) {
  std::fprintf(stderr, "%splanet: error: %s\n", isatty(fileno(stderr)) ? "\n" : "", e.what());
}

int main(int argc, char** argv) {
  CLI::App app{"planet: a planetary flight and space simulator"};
  app.require_subcommand(1);
  // The techniques with their quality parameters, under --help.
  app.footer(planet::describe_techniques());
  planet::apps::add_capture_command(app);
  planet::apps::add_bench_command(app);
  planet::apps::add_accuracy_command(app);
  planet::apps::add_reference_command(app);
  CLI::App& probe = planet::apps::add_probe_command(app);
  planet::apps::add_probe_atmosphere_commands(probe);
  planet::apps::add_fly_command(app);
  planet::apps::add_techniques_command(app);
  planet::apps::add_probe_sun_command(probe);
  planet::apps::add_probe_ground_command(probe);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help arrives as a ParseError that exits 0; anything else the
    // parser rejects is bad input like the rest: one line, status 2.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "planet: error: %s (--help lists the options)\n", e.what());
    return 2;
  } catch (const planet::InputError& e) {
    report(e);
    return 2;
  } catch (const std::exception& e) {
    report(e);
    return 1;
  }
  return 0;
}
