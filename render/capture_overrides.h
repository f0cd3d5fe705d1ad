#pragma once
// A capture's command line over its flight script: `--technique` for the
// script's technique, `--width`/`--height` or `--scale` for its image size,
// to make a small test capture, say, without editing the flight. The
// sidecars and capture.json record what was overridden and what the script
// had.
#include "sim/flight_script.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace planet {

struct CaptureOverrides {
  std::optional<std::string> technique;  // name[:key=value,...]
  // Either side alone keeps the script's aspect ratio.
  std::optional<int> width, height;
  std::optional<double> scale;  // of both sides, rounded to whole pixels
  // What the script had, filled in by apply_capture_overrides.
  std::string script_technique;
  int script_width = 0, script_height = 0;

  bool any() const { return technique || width || height || scale; }
};

// Checks the overrides (InputError naming the option and the value) and
// puts them into `script`, which then names its technique (the governor is
// off, as with a technique in the file); keeps what the script had.
void apply_capture_overrides(FlightScript& script, CaptureOverrides& overrides);

// {"technique": {"script": ..., "command_line": ...}, "image_size": {...}}
// for what was overridden; an empty object where nothing was.
nlohmann::json overrides_json(const CaptureOverrides& overrides);

}  // namespace planet
