// planet_fuzz_replay TARGET PATH...: runs one fuzz target on files, as
// libFuzzer would on a crash's input, without libFuzzer (so with any
// compiler). A folder stands for the files in it. The test suite runs it on
// the seed corpus and on every input a fuzzing run found (regressions/):
// the exit status is 0 only if each was answered without a crash.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#define PLANET_DECLARE(name) int planet_fuzz_##name(const uint8_t* data, size_t size);
PLANET_DECLARE(body)
PLANET_DECLARE(flight)
PLANET_DECLARE(obj_cage)
PLANET_DECLARE(height_map)
PLANET_DECLARE(grid_height)
PLANET_DECLARE(reference_sums)
PLANET_DECLARE(reference_exr)
PLANET_DECLARE(lab_tables)
PLANET_DECLARE(measured_sky)
PLANET_DECLARE(error_model)
PLANET_DECLARE(command_line)
PLANET_DECLARE(surface_maps)

int main(int argc, char** argv) {
  using Target = int (*)(const uint8_t*, size_t);
  const std::map<std::string, Target> targets = {
      {"body", planet_fuzz_body},
      {"flight", planet_fuzz_flight},
      {"obj_cage", planet_fuzz_obj_cage},
      {"height_map", planet_fuzz_height_map},
      {"grid_height", planet_fuzz_grid_height},
      {"reference_sums", planet_fuzz_reference_sums},
      {"reference_exr", planet_fuzz_reference_exr},
      {"lab_tables", planet_fuzz_lab_tables},
      {"measured_sky", planet_fuzz_measured_sky},
      {"error_model", planet_fuzz_error_model},
      {"command_line", planet_fuzz_command_line},
      {"surface_maps", planet_fuzz_surface_maps},
  };
  auto target = argc >= 2 ? targets.find(argv[1]) : targets.end();
  if (target == targets.end()) {
    std::fprintf(stderr, "usage: planet_fuzz_replay TARGET PATH... (targets:");
    for (const auto& [name, f] : targets) std::fprintf(stderr, " %s", name.c_str());
    std::fprintf(stderr, ")\n");
    return 2;
  }
  std::vector<std::filesystem::path> files;
  for (int i = 2; i < argc; ++i) {
    std::filesystem::path p = argv[i];
    if (std::filesystem::is_directory(p)) {
      std::vector<std::filesystem::path> inside;
      for (const auto& entry : std::filesystem::directory_iterator(p)) {
        if (entry.is_regular_file()) inside.push_back(entry.path());
      }
      std::sort(inside.begin(), inside.end());
      files.insert(files.end(), inside.begin(), inside.end());
    } else if (std::filesystem::is_regular_file(p)) {
      files.push_back(p);
    } else {
      std::fprintf(stderr, "planet_fuzz_replay: %s: no such file or folder\n", p.c_str());
      return 2;
    }
  }
  for (const auto& file : files) {
    // Said before each input: a crash leaves the name of the one at fault last.
    std::fprintf(stderr, "replay %s %s\n", argv[1], file.c_str());
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    target->second(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%s: %zu inputs, each answered without a crash\n", argv[1], files.size());
  return 0;
}
