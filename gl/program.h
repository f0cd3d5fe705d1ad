#pragma once
// Shader programs loaded from files under the project root, with
// `#include "path"` resolved relative to the project root, so that the
// atmosphere's shared math (atmosphere/shaders/*.glsl) is one file used by
// every shader and by the C++ tests.
#include <epoxy/gl.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace planet {

// Reads a shader file and splices its includes (each file once). `defines`
// are placed after the #version line.
std::string load_shader_source(const std::filesystem::path& file,
                               const std::vector<std::string>& defines = {});

class Program {
 public:
  Program() = default;
  // Paths are relative to the project root. Throws SystemError with the
  // driver's log and the file names on a compile or link error.
  static Program graphics(const std::string& vertex, const std::string& fragment,
                          const std::vector<std::string>& defines = {});
  static Program compute(const std::string& compute, const std::vector<std::string>& defines = {});

  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }
  // -1 when the uniform is absent or optimised away, as GL does.
  GLint uniform(const char* name) const;

 private:
  explicit Program(GLuint id) : id_(id) {}
  void release();  // deletes the program (counted in gl/live_objects.h)
  GLuint id_ = 0;
  mutable std::map<std::string, GLint> uniforms_;
};

}  // namespace planet
