#pragma once
// One program's variants in one table: each variant's name and the
// defines it compiles with (after the program's own), so that every
// compile of the program takes its defines from the table and a variant
// is named where it is drawn, not assembled there. Each variant is
// compiled when first asked for, once.
#include "gl/program.h"

#include <map>
#include <string>
#include <vector>

namespace planet {

struct ProgramVariant {
  std::string name;
  std::vector<std::string> defines;
  // A vertex shader of its own (a graphics program); empty: the table's.
  std::string vertex = {};
};

class ProgramVariants {
 public:
  ProgramVariants() = default;
  // A compute program's variants: `vertex` empty. `defines` go before each
  // variant's own.
  ProgramVariants(std::string vertex, std::string shader, std::vector<std::string> defines,
                  std::vector<ProgramVariant> variants);

  // The variant's program, compiled the first time; std::logic_error for a
  // name not in the table.
  const Program& operator[](const std::string& name);
  // What the variant compiles with: the program's defines, then its own.
  std::vector<std::string> defines(const std::string& name) const;
  // Compiles the variants named now rather than when first drawn.
  void compile(const std::vector<std::string>& names);
  bool compiled(const std::string& name) const { return programs_.count(name) > 0; }

 private:
  const ProgramVariant& variant(const std::string& name) const;

  std::string vertex_, shader_;
  std::vector<std::string> defines_;
  std::vector<ProgramVariant> variants_;
  std::map<std::string, Program> programs_;
};

}  // namespace planet
