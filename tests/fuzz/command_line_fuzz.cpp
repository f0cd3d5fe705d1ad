// The command line: the input is argv (words separated by NUL bytes),
// parsed by the very app `planet` builds, stopped once it is parsed and
// checked (a parse that succeeds runs nothing). Each word is also given to the
// parsers of the options' values (techniques, path budgets, times, shares).
#include "apps/cli.h"
#include "atmosphere/gpu/registry.h"
#include "atmosphere/reference/medium.h"
#include "atmosphere/reference/path_budget.h"
#include "core/share.h"
#include "fuzz_input.h"
#include "governor/governor.h"
#include "lab/stability.h"
#include "sim/utc_time.h"

#include <vector>

namespace {

// Thrown once the whole command line has been parsed and checked, before
// any command's work would run; not a std::exception, so that run_cli lets
// it through.
struct Parsed {};

}  // namespace

PLANET_FUZZ_TARGET(command_line) {
  std::string_view text = planet::fuzz::as_text(data, size);
  std::vector<std::string> words{"planet"};
  for (size_t start = 0; start <= text.size() && words.size() < 32;) {
    size_t end = text.find('\0', start);
    if (end == std::string_view::npos) end = text.size();
    words.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());

  std::unique_ptr<CLI::App> app = planet::apps::make_cli();
  // The root's parse-complete callback runs after every option is stored
  // and checked, and before the subcommands' own callbacks (the work).
  app->parse_complete_callback([] { throw Parsed{}; });
  int status = 0;
  try {
    status = planet::apps::run_cli(*app, int(argv.size()), argv.data());
  } catch (const Parsed&) {
  }
  if (status != 0 && status != 2) {
    std::fprintf(stderr, "fuzz: the command line exited %d, not 0 or 2\n", status);
    std::abort();
  }

  for (size_t i = 1; i < words.size(); ++i) {
    const std::string& w = words[i];
    using namespace planet;
    fuzz::expect_only_input_errors([&] { (void)parse_technique(w); });
    fuzz::expect_only_input_errors([&] { (void)PathBudget::parse(w); });
    fuzz::expect_only_input_errors([&] { (void)parse_utc(w, "--time"); });
    fuzz::expect_only_input_errors([&] { (void)parse_share(w, "--shard"); });
    fuzz::expect_only_input_errors([&] { (void)parse_shard(w); });
    fuzz::expect_only_input_errors([&] { (void)parse_reference_mode(w); });
  }
  return 0;
}
