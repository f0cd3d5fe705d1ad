// planet: a thin command line over the modules. Each subcommand parses its
// options, calls one function of render/, and reports; every error is
// caught here once and printed as one line.
#include "render/capture.h"
#include "render/gl/context.h"
#include "sim/error.h"
#include "sim/flight_script.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <string>

namespace {

// "A:B" (B exclusive), "A:" or ":B".
std::pair<int, int> parse_frame_range(const std::string& text) {
  auto colon = text.find(':');
  if (colon == std::string::npos) {
    throw planet::InputError(fmt::format("--frames '{}': expected A:B (B exclusive)", text));
  }
  auto parse = [&](const std::string& s, int fallback) {
    if (s.empty()) return fallback;
    size_t used = 0;
    int v = -1;
    try {
      v = std::stoi(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || v < 0) {
      throw planet::InputError(fmt::format("--frames '{}': '{}' is not a frame number", text, s));
    }
    return v;
  };
  return {parse(text.substr(0, colon), 0), parse(text.substr(colon + 1), -1)};
}

int run_capture_command(const std::string& flight_file, const std::string& out_dir,
                        const std::string& frames, bool quiet) {
  planet::FlightScript script = planet::load_flight_script(flight_file);
  planet::CaptureOptions options;
  options.out_dir = out_dir.empty() ? std::filesystem::path("out") / script.name
                                    : std::filesystem::path(out_dir);
  if (!frames.empty()) std::tie(options.first_frame, options.end_frame) = parse_frame_range(frames);
  options.progress = !quiet;
  auto context = planet::GlContext::create_headless();
  if (!quiet) {
    std::fprintf(stderr, "planet: %s, %dx%d, %d frames at %g fps, %s sky on %s\n",
                 script.body.name.c_str(), script.width, script.height, script.frame_count(),
                 script.frame_rate, script.technique.c_str(), context->renderer().c_str());
  }
  planet::CaptureResult result = planet::run_capture(script, options);
  std::printf("captured %d frames in %.1f s into %s (first %s, last %s)\n", result.frames,
              result.wall_seconds, options.out_dir.string().c_str(),
              result.first_png.filename().string().c_str(),
              result.last_png.filename().string().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"planet: a planetary flight and space simulator"};
  app.require_subcommand(1);

  std::string flight_file, out_dir, frames;
  bool quiet = false;
  CLI::App* capture =
      app.add_subcommand("capture", "Render a scripted flight headless into EXR + PNG frames");
  capture->add_option("--flight", flight_file, "Flight script (data/flights/*.json)")
      ->required();
  capture->add_option("--out", out_dir, "Output folder (default out/<flight name>)");
  capture->add_option("--frames", frames, "Slice of frames A:B to render (B exclusive)");
  capture->add_flag("--quiet", quiet, "No progress output");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    if (*capture) return run_capture_command(flight_file, out_dir, frames, quiet);
  } catch (const planet::InputError& e) {
    std::fprintf(stderr, "\nplanet: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "\nplanet: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
