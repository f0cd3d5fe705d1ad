// planet: a thin command line over the modules. Each subcommand registers
// itself (apps/commands.h) and does its work in its callback; every error
// is caught here once and printed as one line.
#include "apps/commands.h"
#include "atmosphere/gpu/registry.h"
#include "core/error.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <string>

// The first word that names no command where one is required (`planet
// fly` spelt `planet flz`, `planet probe wind`), as one line; CLI11 would
// only say that a subcommand is required.
static std::string unknown_command(CLI::App& app, int argc, char** argv) {
  CLI::App* level = &app;
  std::string path = "planet";
  auto names = [](CLI::App* a) {
    std::string out;
    for (CLI::App* sub : a->get_subcommands([](CLI::App*) { return true; })) {
      out += (out.empty() ? "" : ", ") + sub->get_name();
    }
    return out;
  };
  for (int i = 1; i < argc; ++i) {
    std::string word = argv[i];
    if (word.empty() || word[0] == '-') return {};
    auto subs = level->get_subcommands([](CLI::App*) { return true; });
    if (subs.empty()) return {};
    CLI::App* next = nullptr;
    for (CLI::App* sub : subs) {
      if (sub->check_name(word)) next = sub;
    }
    if (!next) return fmt::format("'{}' is not a command of {} ({})", word, path, names(level));
    level = next;
    path += " " + word;
  }
  if (level->get_require_subcommand_min() > 0) {
    return fmt::format("{} needs a command: {} ({} --help says more)", path, names(level), path);
  }
  return {};
}

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
  planet::apps::add_cluster_command(app);
  CLI::App& probe = planet::apps::add_probe_command(app);
  planet::apps::add_probe_atmosphere_commands(probe);
  planet::apps::add_fly_command(app);
  planet::apps::add_techniques_command(app);
  planet::apps::add_lab_command(app);
  planet::apps::add_probe_sun_command(probe);
  planet::apps::add_probe_ground_command(probe);
  planet::apps::add_probe_oneil_command(probe);

  if (std::string unknown = unknown_command(app, argc, argv); !unknown.empty()) {
    std::fprintf(stderr, "planet: error: %s\n", unknown.c_str());
    return 2;
  }
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
