#include "apps/cli.h"

#include "apps/cli_options.h"
#include "apps/commands.h"
#include "core/error.h"
#include "core/version.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace planet::apps {

namespace {

std::string subcommand_names(CLI::App* app) {
  std::string out;
  for (CLI::App* sub : app->get_subcommands([](CLI::App*) { return true; })) {
    out += (out.empty() ? "" : ", ") + sub->get_name();
  }
  return out;
}

// One line on stderr; on a terminal, first end any progress line.
void report(const std::exception& e) {
  std::fprintf(stderr, "%splanet: error: %s\n", isatty(fileno(stderr)) ? "\n" : "", e.what());
}

}  // namespace

std::unique_ptr<CLI::App> make_cli() {
  auto app = std::make_unique<CLI::App>(
      "planet: a planetary flight and space simulator. Bodies: " + body_list_text() + ".");
  app->require_subcommand(1);
  app->set_version_flag("--version", "planet " + planet_version(), "Print the version and exit");
  // Each command inherits this footer unless it sets its own. The table of
  // techniques is 60 lines: under every --help it drowned the options.
  app->footer(
      "`planet techniques` lists the atmosphere techniques and their quality parameters. A list "
      "option takes its items with commas or spaces between them (--bodies earth,mars or "
      "--bodies earth mars).");
  add_capture_command(*app);
  add_bench_command(*app);
  add_accuracy_command(*app);
  add_reference_command(*app);
  add_cluster_command(*app);
  add_eclipse_command(*app);
  CLI::App& probe = add_probe_command(*app);
  add_probe_atmosphere_commands(probe);
  add_fly_command(*app);
  add_soak_command(*app);
  add_techniques_command(*app);
  add_lab_command(*app);
  add_probe_sun_command(probe);
  add_probe_moon_command(probe);
  add_probe_ground_command(probe);
  add_probe_oneil_command(probe);
  return app;
}

std::string unknown_command(CLI::App& app, int argc, const char* const* argv) {
  CLI::App* level = &app;
  std::string path = "planet";
  for (int i = 1; i < argc; ++i) {
    std::string word = argv[i];
    if (word.empty() || word[0] == '-') return {};
    auto subs = level->get_subcommands([](CLI::App*) { return true; });
    if (subs.empty()) return {};
    CLI::App* next = nullptr;
    for (CLI::App* sub : subs) {
      if (sub->check_name(word)) next = sub;
    }
    if (!next) {
      return fmt::format("'{}' is not a command of {} ({})", word, path, subcommand_names(level));
    }
    level = next;
    path += " " + word;
  }
  if (level->get_require_subcommand_min() > 0) {
    return fmt::format("{} needs a command: {} ({} --help says more)", path,
                       subcommand_names(level), path);
  }
  return {};
}

int run_cli(CLI::App& app, int argc, const char* const* argv) {
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
  } catch (const InputError& e) {
    report(e);
    return 2;
  } catch (const std::exception& e) {
    report(e);
    return 1;
  }
  return 0;
}

}  // namespace planet::apps
