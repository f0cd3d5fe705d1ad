#include "atmosphere/reference/render_sums.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace planet {

int64_t RenderSums::traced() const {
  int64_t n = 0;
  for (int d : done) n += d;
  return n;
}

bool RenderSums::fits(const std::vector<int>& lane_paths) const {
  if (done.size() != lane_paths.size()) return false;
  for (size_t lane = 0; lane < done.size(); ++lane) {
    if (done[lane] < 0 || done[lane] > lane_paths[lane]) return false;
  }
  return true;
}

namespace {

constexpr const char* kSumsMagic = "planet reference sums 1";

}  // namespace

void write_sums(const std::filesystem::path& file, const std::string& view_key,
                const RenderSums& sums) {
  std::string header = fmt::format("{}\n{}\n{} {} {}\n", kSumsMagic, view_key, sums.width,
                                   sums.height, sums.done.size());
  for (size_t i = 0; i < sums.done.size(); ++i) {
    header += fmt::format("{}{}", i ? " " : "", sums.done[i]);
  }
  header += "\n";
  std::string bytes = header;
  bytes.append(reinterpret_cast<const char*>(sums.sum.data()), sums.sum.size() * sizeof(double));
  write_file_atomically(file, bytes);
}

std::optional<RenderSums> read_sums(const std::filesystem::path& file,
                                    const std::string& view_key) {
  std::ifstream in(file, std::ios::binary);
  auto bad = [&](const std::string& what) {
    return InputError(
        fmt::format("{}: {} (delete it and the render starts from nothing)", file.string(), what));
  };
  std::string magic, key;
  std::getline(in, magic);
  std::getline(in, key);
  if (!in || magic != kSumsMagic) throw bad("not the sums of a reference render");
  if (key != view_key) return std::nullopt;
  RenderSums sums;
  size_t lanes = 0;
  in >> sums.width >> sums.height >> lanes;
  if (!in || sums.width < 1 || sums.height < 1 || lanes < 1 || lanes > 1024) {
    throw bad("its size line is not 'width height lanes'");
  }
  sums.done.resize(lanes);
  for (int& n : sums.done) in >> n;
  if (!in || in.get() != '\n' ||
      std::any_of(sums.done.begin(), sums.done.end(), [](int n) { return n < 0; })) {
    throw bad("its paths line does not give one count (0 or more) per lane");
  }
  // The sums the header promises must be in the file before any memory is
  // given to them: a header that claims a billion pixels is not sums.
  const uint64_t count = uint64_t(sums.width) * uint64_t(sums.height) * lanes;
  std::error_code ec;
  const uint64_t file_bytes = std::filesystem::file_size(file, ec);
  const auto header_bytes = uint64_t(in.tellg());
  if (ec || count > (file_bytes - std::min(file_bytes, header_bytes)) / sizeof(double)) {
    throw bad(fmt::format("its header promises {} x {} x {} sums, more than it holds",
                          sums.width, sums.height, lanes));
  }
  sums.sum.resize(count);
  in.read(reinterpret_cast<char*>(sums.sum.data()),
          std::streamsize(sums.sum.size() * sizeof(double)));
  if (!in || in.peek() != std::char_traits<char>::eof()) {
    throw bad(fmt::format("it should hold {} sums after its header", sums.sum.size()));
  }
  if (!std::all_of(sums.sum.begin(), sums.sum.end(), [](double v) { return std::isfinite(v); })) {
    throw bad("it holds a sum that is not a finite number");
  }
  return sums;
}

}  // namespace planet
