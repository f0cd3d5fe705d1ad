#pragma once
// Each subcommand of `planet` lives in its own file and registers itself on
// the CLI11 app here; main() only parses and catches. A registration
// function adds the subcommand with its options and a callback that does
// the work (CLI11 runs the callback after a successful parse).
#include <CLI/CLI.hpp>

namespace planet::apps {

void add_capture_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_accuracy_command(CLI::App& app);
void add_reference_command(CLI::App& app);
// `planet cluster slurm|kubernetes`: a command split over a scheduler.
void add_cluster_command(CLI::App& app);
// `planet eclipse DATE`: the circumstances of that day's eclipse.
void add_eclipse_command(CLI::App& app);
// `planet probe <quantity>`: the probe parent, to which modules add their
// quantities (transmittance, sky, sun, ...).
CLI::App& add_probe_command(CLI::App& app);
// `planet probe transmittance` and `planet probe sky`.
void add_probe_atmosphere_commands(CLI::App& probe);
void add_fly_command(CLI::App& app);
// `planet soak`: a long flight that fails if anything grows.
void add_soak_command(CLI::App& app);
// `planet techniques`: the registry of atmosphere techniques.
void add_techniques_command(CLI::App& app);
void add_lab_command(CLI::App& app);
// `planet lab measured`, added to the lab parent by add_lab_command.
void add_lab_measured_command(CLI::App& lab);
// `planet lab clarity`, added the same way.
void add_lab_clarity_command(CLI::App& lab);
// The python3 that imports matplotlib, for a command's charts; InputError
// naming `what` (the command) where there is none. Said before any work.
std::string matplotlib_python(const std::string& what);
void add_probe_sun_command(CLI::App& probe);
// `planet probe moon`: the Moon's light over a place on Earth.
void add_probe_moon_command(CLI::App& probe);
// `planet probe ground`: the terrain's height under a place.
void add_probe_ground_command(CLI::App& probe);
// `planet probe oneil-fit`: the oneil technique's fitted scale functions.
void add_probe_oneil_command(CLI::App& probe);

}  // namespace planet::apps
