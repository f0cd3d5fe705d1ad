#pragma once
// What every fuzz target shares. The parsers read files, as the program
// does, so the input is written to a file of this process first. The rule
// each target checks: an InputError is the parser's answer to bad input
// (one line, naming the file); any other exception that escapes, a crash,
// a hang or a sanitizer's report is a finding.
#include "core/error.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

// A target: PLANET_FUZZ_TARGET(body) { ...data, size... return 0; } defines
// planet_fuzz_body(data, size), and, built for libFuzzer, its entry point.
// Without libFuzzer the targets are linked together into
// planet_fuzz_replay, which runs them on files (the corpus and every
// finding, in the test suite).
#ifdef PLANET_LIBFUZZER
#define PLANET_FUZZ_ENTRY(name)                                               \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { \
    return planet_fuzz_##name(data, size);                                  \
  }
#else
#define PLANET_FUZZ_ENTRY(name)
#endif
#define PLANET_FUZZ_TARGET(name)                               \
  int planet_fuzz_##name(const uint8_t* data, size_t size);    \
  PLANET_FUZZ_ENTRY(name)                                      \
  int planet_fuzz_##name(const uint8_t* data, size_t size)

namespace planet::fuzz {

// A folder of this process's own under $TMPDIR, removed at exit.
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("planet-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch_dir(), ec);
    });
    return d;
  }();
  return dir;
}

inline std::filesystem::path write_input(std::string_view bytes, const std::string& name) {
  std::filesystem::path file = scratch_dir() / name;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  return file;
}

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `parse`; an InputError is the expected refusal, and it must say
// something. Anything else that escapes is reported and aborts the run.
template <class F>
void expect_only_input_errors(F&& parse) {
  try {
    parse();
  } catch (const InputError& e) {
    if (std::string_view(e.what()).empty()) {
      std::fprintf(stderr, "fuzz: an InputError without a message\n");
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not an InputError: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: something that is not an exception was thrown\n");
    std::abort();
  }
}

}  // namespace planet::fuzz
