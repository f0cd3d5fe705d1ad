#pragma once
// The command line of `planet`: every subcommand registered on one CLI11
// app, and the one place its errors are caught and printed. main() builds
// it and runs it; the command line's fuzz target (tests/fuzz) builds the
// same app with the subcommands' work taken out and feeds it argv.
#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace planet::apps {

// The app with every subcommand and its options.
std::unique_ptr<CLI::App> make_cli();

// The first word that names no command where one is required (`planet
// fly` spelt `planet flz`, `planet probe wind`), as one line; empty when
// every word names one. CLI11 itself would only say that a subcommand is
// required.
std::string unknown_command(CLI::App& app, int argc, const char* const* argv);

// Parses argv and runs the chosen command: the process's exit status (0;
// 2 for bad input, said in one line on stderr; 1 for anything else).
int run_cli(CLI::App& app, int argc, const char* const* argv);

}  // namespace planet::apps
