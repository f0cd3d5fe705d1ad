#include "gl/program_variants.h"

#include <fmt/format.h>

#include <stdexcept>

namespace planet {

ProgramVariants::ProgramVariants(std::string vertex, std::string shader,
                                 std::vector<std::string> defines,
                                 std::vector<ProgramVariant> variants)
    : vertex_(std::move(vertex)),
      shader_(std::move(shader)),
      defines_(std::move(defines)),
      variants_(std::move(variants)) {
  for (size_t i = 0; i < variants_.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (variants_[i].name == variants_[j].name) {
        throw std::logic_error(
            fmt::format("{} has two variants named \"{}\"", shader_, variants_[i].name));
      }
    }
  }
}

const ProgramVariant& ProgramVariants::variant(const std::string& name) const {
  for (const ProgramVariant& v : variants_) {
    if (v.name == name) return v;
  }
  throw std::logic_error(fmt::format("{} has no variant \"{}\"", shader_, name));
}

std::vector<std::string> ProgramVariants::defines(const std::string& name) const {
  std::vector<std::string> all = defines_;
  const ProgramVariant& v = variant(name);
  all.insert(all.end(), v.defines.begin(), v.defines.end());
  return all;
}

const Program& ProgramVariants::operator[](const std::string& name) {
  auto it = programs_.find(name);
  if (it != programs_.end()) return it->second;
  const ProgramVariant& v = variant(name);
  const std::string& vertex = v.vertex.empty() ? vertex_ : v.vertex;
  Program program = vertex.empty() ? Program::compute(shader_, defines(name))
                                   : Program::graphics(vertex, shader_, defines(name));
  return programs_.emplace(name, std::move(program)).first->second;
}

void ProgramVariants::compile(const std::vector<std::string>& names) {
  for (const std::string& name : names) (void)(*this)[name];
}

}  // namespace planet
