// The lab's tables that a rerun reads back: a cell of `planet lab run`'s
// sweep and a cell of `planet lab stability`'s map (the same file is
// offered to both readers).
#include "fuzz_input.h"
#include "lab/gpu/sweep.h"
#include "lab/stability.h"

PLANET_FUZZ_TARGET(lab_tables) {
  std::filesystem::path file =
      planet::fuzz::write_input(planet::fuzz::as_text(data, size), "cell.json");
  planet::fuzz::expect_only_input_errors([&] { (void)planet::read_sweep_cell(file); });
  planet::fuzz::expect_only_input_errors([&] { (void)planet::read_stability_result(file); });
  return 0;
}
