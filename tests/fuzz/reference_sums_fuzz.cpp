// The reference cache's checkpoints (.sums): a header and the running sums.
// The view key asked for is the file's own second line, so that the input
// gets past the key and into the sizes and the sums.
#include "atmosphere/reference/render_sums.h"
#include "fuzz_input.h"

PLANET_FUZZ_TARGET(reference_sums) {
  std::string_view text = planet::fuzz::as_text(data, size);
  std::string key;
  if (size_t first = text.find('\n'); first != std::string_view::npos) {
    size_t second = text.find('\n', first + 1);
    key = std::string(text.substr(first + 1, second == std::string_view::npos
                                                  ? std::string_view::npos
                                                  : second - first - 1));
  }
  std::filesystem::path file = planet::fuzz::write_input(text, "cache.sums");
  planet::fuzz::expect_only_input_errors([&] {
    if (auto sums = planet::read_sums(file, key)) {
      (void)sums->traced();
      (void)sums->fits(sums->done);
    }
  });
  return 0;
}
