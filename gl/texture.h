#pragma once
// Small owning wrappers for GL objects, so that a thrown error never leaks
// them and a moved-from object deletes nothing.
#include "gl/live_objects.h"

#include <epoxy/gl.h>

#include <initializer_list>
#include <utility>
#include <vector>

namespace planet {

template <GlObjectKind Kind, void (*Delete)(GLuint)>
class GlName {
 public:
  GlName() = default;
  // Takes ownership of a name just made.
  explicit GlName(GLuint id) : id_(id) {
    if (id_) note_gl_objects(Kind, 1);
  }
  ~GlName() { release(); }
  GlName(GlName&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) {
      release();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GLuint id() const { return id_; }

 private:
  void release() {
    if (!id_) return;
    Delete(id_);
    note_gl_objects(Kind, -1);
  }
  GLuint id_ = 0;
};

inline void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
inline void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }

using Texture = GlName<GlObjectKind::texture, delete_texture>;
using Buffer = GlName<GlObjectKind::buffer, delete_buffer>;
using Framebuffer = GlName<GlObjectKind::framebuffer, delete_framebuffer>;
using VertexArray = GlName<GlObjectKind::vertex_array, delete_vertex_array>;

// Immutable 2D and 3D textures with linear filtering and clamped edges.
Texture make_texture_2d(GLenum internal_format, int width, int height);
Texture make_texture_3d(GLenum internal_format, int width, int height, int depth);
// A multisampled 2D texture (fixed sample locations), for a pass that
// resolves it itself.
Texture make_texture_2d_multisample(GLenum internal_format, int samples, int width, int height);
// A framebuffer of a colour texture and, unless 0, a depth texture and a
// stencil texture; SystemError when GL finds it incomplete.
Framebuffer make_framebuffer(GLuint color, GLuint depth, GLuint stencil = 0);
// The same with several colour textures, drawn to as outputs 0, 1, ...
Framebuffer make_framebuffer(std::initializer_list<GLuint> colors, GLuint depth,
                             GLuint stencil = 0);
// Binds the framebuffer and its viewport, clears its colour and its depth
// to the far plane of reversed Z (0), and tests depth as reversed Z wants
// it (nearer is greater): how every pass of opaque surfaces begins.
void begin_reversed_z(GLuint framebuffer, int width, int height, const float clear_color[4]);
// A buffer with immutable storage, optionally filled.
Buffer make_buffer(size_t bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);

// Reads a whole RGBA float texture (level 0) back to the CPU, rows bottom-up.
std::vector<float> read_texture_rgba32f(GLuint texture, int width, int height);

}  // namespace planet
