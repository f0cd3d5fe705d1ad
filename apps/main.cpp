// planet: a thin command line over the modules. Each subcommand registers
// itself (apps/commands.h) and does its work in its callback; every error
// is caught once (apps/cli.h) and printed as one line.
#include "apps/cli.h"

#include <malloc.h>

#include <csignal>
#include <cstdlib>

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f) a write then fails with EFBIG, which
  // the writer reports naming the file, rather than the signal killing the
  // process in the middle of a frame.
  std::signal(SIGXFSZ, SIG_IGN);
  // One malloc arena for every thread. With glibc's default (one per
  // thread that allocates, up to eight per core: the tile worker, the
  // driver's rasterizer threads) each arena keeps its own free pages, and
  // over a long flight the resident memory crept up by a few percent while
  // the heap in use stayed flat (`planet soak`: docs/testing.md#soak). The
  // threads allocate little in their hot loops: the path tracer's two
  // threads traced 1.03-1.13e5 paths/s with one arena, 0.96-1.12e5 with
  // eight (earth_sunset 8x4). MALLOC_ARENA_MAX in the environment wins.
  if (!std::getenv("MALLOC_ARENA_MAX")) mallopt(M_ARENA_MAX, 1);
  // Blocks of 1 MiB and more (the driver's textures, images read back) are
  // mapped and unmapped on their own. By default glibc raises that
  // threshold to the largest block freed so far (up to 32 MiB), after which
  // the Bruneton tables of a technique switch came from the heap and left
  // it fragmented: the soak's peak wandered by 10 MiB from round to round.
  // MALLOC_MMAP_THRESHOLD_ in the environment wins.
  if (!std::getenv("MALLOC_MMAP_THRESHOLD_")) mallopt(M_MMAP_THRESHOLD, 1 << 20);
  std::unique_ptr<CLI::App> app = planet::apps::make_cli();
  return planet::apps::run_cli(*app, argc, argv);
}
