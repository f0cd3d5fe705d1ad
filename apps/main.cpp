// planet: a thin command line over the modules. Each subcommand registers
// itself (apps/commands.h) and does its work in its callback; every error
// is caught once (apps/cli.h) and printed as one line.
#include "apps/cli.h"

#include <csignal>

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f) a write then fails with EFBIG, which
  // the writer reports naming the file, rather than the signal killing the
  // process in the middle of a frame.
  std::signal(SIGXFSZ, SIG_IGN);
  std::unique_ptr<CLI::App> app = planet::apps::make_cli();
  return planet::apps::run_cli(*app, argc, argv);
}
