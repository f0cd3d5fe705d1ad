#include "terrain/obj_cage.h"

#include "core/error.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

namespace planet {

namespace {

std::string where(const std::filesystem::path& file, int line) {
  return fmt::format("{}:{}", file.string(), line);
}

}  // namespace

ObjCage read_obj_cage(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot read OBJ cage", file.string()));

  ObjCage cage;
  std::vector<int> face_lines;  // the line of each face, for the messages
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream s(text);
    std::string key;
    if (!(s >> key)) continue;
    if (key == "v") {
      // Parsed as text with from_chars, which reads "nan" and "inf" as
      // such, so that they are caught below rather than as bad syntax.
      glm::dvec3 p(0.0);
      for (int i = 0; i < 3; ++i) {
        std::string word;
        if (!(s >> word)) {
          throw InputError(fmt::format("{}: vertex needs three coordinates", where(file, line)));
        }
        auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), p[i]);
        if (ec != std::errc() || end != word.data() + word.size()) {
          throw InputError(
              fmt::format("{}: '{}' is not a vertex coordinate", where(file, line), word));
        }
      }
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw InputError(fmt::format("{}: vertex {} is not a finite number", where(file, line),
                                     cage.vertices.size() + 1));
      }
      cage.vertices.push_back(p);
    } else if (key == "f") {
      int n = 0;
      std::string word;
      while (s >> word) {
        // Only the position index before the first '/' matters.
        std::string v = word.substr(0, word.find('/'));
        long index = 0;
        auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), index);
        if (ec != std::errc() || end != v.data() + v.size() || index == 0) {
          throw InputError(fmt::format("{}: '{}' is not a vertex index", where(file, line), word));
        }
        long count = long(cage.vertices.size());
        long zero_based = index > 0 ? index - 1 : count + index;
        if (zero_based < 0 || zero_based >= count) {
          throw InputError(fmt::format("{}: vertex index {} is out of range (1 to {})",
                                       where(file, line), index, count));
        }
        cage.face_indices.push_back(int(zero_based));
        ++n;
      }
      if (n < 3) {
        throw InputError(
            fmt::format("{}: a face needs at least three vertices", where(file, line)));
      }
      cage.face_sizes.push_back(n);
      face_lines.push_back(line);
    }
  }
  if (in.bad()) throw InputError(fmt::format("{}: cannot read OBJ cage", file.string()));
  if (cage.face_sizes.empty()) {
    throw InputError(fmt::format("{}: OBJ cage has no faces", file.string()));
  }

  // Merge vertices at the same position (see the header), keeping the first.
  std::map<std::tuple<double, double, double>, int> first;
  std::vector<int> remap(cage.vertices.size());
  std::vector<glm::dvec3> merged;
  for (size_t i = 0; i < cage.vertices.size(); ++i) {
    const glm::dvec3& p = cage.vertices[i];
    auto [it, inserted] = first.try_emplace({p.x, p.y, p.z}, int(merged.size()));
    if (inserted) merged.push_back(p);
    remap[i] = it->second;
  }
  cage.vertices = std::move(merged);
  for (int& i : cage.face_indices) i = remap[size_t(i)];

  // Catmull-Clark needs a closed 2-manifold here: an edge used once is a
  // hole (the surface would not enclose the centre), an edge used three or
  // more times joins sheets that no limit surface can follow.
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // -> (uses, first face line)
  std::set<std::pair<int, int>> directed;
  size_t k = 0;
  for (size_t f = 0; f < cage.face_sizes.size(); ++f) {
    int n = cage.face_sizes[f];
    for (int j = 0; j < n; ++j) {
      int a = cage.face_indices[k + size_t(j)], b = cage.face_indices[k + size_t((j + 1) % n)];
      if (a == b) {
        throw InputError(fmt::format("{}: face repeats vertex {} (degenerate edge)",
                                     where(file, face_lines[f]), a + 1));
      }
      auto [it, inserted] = edges.try_emplace({std::min(a, b), std::max(a, b)}, 0, face_lines[f]);
      if (++it->second.first > 2) {
        throw InputError(fmt::format(
            "{}: non-manifold cage: the edge between vertices {} and {} is shared by more than "
            "two faces",
            where(file, face_lines[f]), it->first.first + 1, it->first.second + 1));
      }
      // Each face of a consistently oriented closed cage runs along a
      // shared edge the other way from its neighbour; OpenSubdiv needs that
      // to find a vertex's ring of faces.
      if (!directed.insert({a, b}).second) {
        throw InputError(fmt::format(
            "{}: faces are not consistently oriented: two faces run from vertex {} to {}",
            where(file, face_lines[f]), a + 1, b + 1));
      }
    }
    k += size_t(n);
  }
  for (const auto& [edge, use] : edges) {
    if (use.first == 1) {
      throw InputError(fmt::format(
          "{}: the cage is not closed: the edge between vertices {} and {} borders only one face",
          where(file, use.second), edge.first + 1, edge.second + 1));
    }
  }
  return cage;
}

}  // namespace planet
