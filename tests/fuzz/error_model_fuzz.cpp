// The governor's error-and-cost table (data/lab/error_model.json, or
// --error-model FILE): read, then asked to choose at each of its own views
// and between them, as a flight would.
#include "fuzz_input.h"
#include "governor/governor.h"

PLANET_FUZZ_TARGET(error_model) {
  std::filesystem::path file =
      planet::fuzz::write_input(planet::fuzz::as_text(data, size), "error_model.json");
  planet::fuzz::expect_only_input_errors([&] {
    planet::ErrorModel model = planet::load_error_model(file);
    std::vector<planet::ViewFeatures> views;
    for (const planet::ViewClass& c : model.classes) {
      views.push_back(c.view);
      planet::ViewFeatures higher = c.view;
      higher.altitude_m = 2.0 * higher.altitude_m + 1e4;
      views.push_back(higher);
    }
    planet::Governor governor(std::move(model), {}, "hillaire");
    for (const planet::ViewFeatures& view : views) (void)governor.decide(view);
  });
  return 0;
}
