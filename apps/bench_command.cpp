// planet bench: Google Benchmark over the benchmarks linked into the
// program (apps/bench/*.cpp). Timings on llvmpipe are CPU timings: compare
// techniques as ratios within one run, never across machines.
#include "apps/commands.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace planet {
void register_sky_benchmarks();  // apps/bench/sky_bench.cpp
}

namespace planet::apps {

void add_bench_command(CLI::App& app) {
  CLI::App* cmd =
      app.add_subcommand("bench",
                         "Run the speed benchmarks (Google Benchmark; its flags follow, "
                         "e.g. planet bench --benchmark_filter=Hillaire)");
  // Everything after `bench` goes to Google Benchmark as it is.
  cmd->prefix_command();
  cmd->callback([cmd] {
    std::vector<std::string> args = {"planet bench"};
    for (const auto& e : cmd->remaining()) args.push_back(e);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    int argc = int(argv.size());
    register_sky_benchmarks();
    benchmark::Initialize(&argc, argv.data());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  });
}

CLI::App& add_probe_command(CLI::App& app) {
  CLI::App* probe = app.add_subcommand("probe", "Print model quantities for given inputs");
  probe->require_subcommand(1);
  return *probe;
}

}  // namespace planet::apps
