#include "gl/program.h"

#include "core/data_paths.h"
#include "core/error.h"
#include "gl/live_objects.h"

#include <fmt/format.h>

#include <fstream>
#include <set>
#include <sstream>

namespace planet {

namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw SystemError(fmt::format("{}: cannot read shader file", path.string()));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// GLSL has no file names in #line, so each spliced file gets a number and
// the error message maps numbers back to names.
void splice(const std::filesystem::path& rel, std::set<std::string>& seen,
            std::vector<std::string>& names, std::ostringstream& out) {
  if (!seen.insert(rel.string()).second) return;
  int index = int(names.size());
  names.push_back(rel.string());
  std::istringstream in(read_file(project_root() / rel));
  std::string line;
  int number = 0;
  out << "#line 1 " << index << "\n";
  while (std::getline(in, line)) {
    ++number;
    auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
      auto open = line.find('"'), close = line.rfind('"');
      if (open == std::string::npos || close == open) {
        throw SystemError(fmt::format("{}:{}: malformed #include", rel.string(), number));
      }
      splice(line.substr(open + 1, close - open - 1), seen, names, out);
      out << "#line " << number + 1 << " " << index << "\n";
    } else {
      out << line << "\n";
    }
  }
}

std::string source_with_version(const std::filesystem::path& file,
                                const std::vector<std::string>& defines,
                                std::vector<std::string>& names) {
  std::ostringstream body;
  std::set<std::string> seen;
  splice(file, seen, names, body);
  std::ostringstream out;
  out << "#version 450 core\n";
  for (const auto& d : defines) out << "#define " << d << "\n";
  out << body.str();
  return out.str();
}

GLuint compile(GLenum stage, const std::string& file, const std::vector<std::string>& defines) {
  std::vector<std::string> names;
  std::string source = source_with_version(file, defines, names);
  GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    std::string legend;
    for (size_t i = 0; i < names.size(); ++i) legend += fmt::format(" {}={}", i, names[i]);
    throw SystemError(
        fmt::format("shader {} does not compile (source numbers:{}):\n{}", file, legend, log));
  }
  return shader;
}

GLuint link(const std::vector<GLuint>& shaders, const std::string& what) {
  GLuint program = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    glDeleteProgram(program);
    throw SystemError(fmt::format("program {} does not link:\n{}", what, log));
  }
  note_gl_objects(GlObjectKind::program, 1);
  return program;
}

}  // namespace

std::string load_shader_source(const std::filesystem::path& file,
                               const std::vector<std::string>& defines) {
  std::vector<std::string> names;
  return source_with_version(file, defines, names);
}

Program Program::graphics(const std::string& vertex, const std::string& fragment,
                          const std::vector<std::string>& defines) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertex, defines);
  GLuint fs = compile(GL_FRAGMENT_SHADER, fragment, defines);
  return Program(link({vs, fs}, vertex + " + " + fragment));
}

Program Program::compute(const std::string& compute, const std::vector<std::string>& defines) {
  return Program(link({planet::compile(GL_COMPUTE_SHADER, compute, defines)}, compute));
}

Program::~Program() { release(); }

void Program::release() {
  if (!id_) return;
  glDeleteProgram(id_);
  note_gl_objects(GlObjectKind::program, -1);
  id_ = 0;
}

Program::Program(Program&& other) noexcept : id_(other.id_), uniforms_(std::move(other.uniforms_)) {
  other.id_ = 0;
}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    release();
    id_ = other.id_;
    uniforms_ = std::move(other.uniforms_);
    other.id_ = 0;
  }
  return *this;
}

GLint Program::uniform(const char* name) const {
  auto it = uniforms_.find(name);
  if (it != uniforms_.end()) return it->second;
  GLint location = glGetUniformLocation(id_, name);
  uniforms_[name] = location;
  return location;
}

}  // namespace planet
