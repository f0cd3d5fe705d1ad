#include "render/gl/texture.h"

namespace planet {

Texture make_texture_2d(GLenum internal_format, int width, int height) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, internal_format, width, height);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return Texture(id);
}

Buffer make_buffer(size_t bytes, const void* data, GLbitfield flags) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferStorage(id, GLsizeiptr(bytes), data, flags);
  return Buffer(id);
}

std::vector<float> read_texture_rgba32f(GLuint texture, int width, int height) {
  std::vector<float> pixels(size_t(width) * size_t(height) * 4);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                    pixels.data());
  return pixels;
}

}  // namespace planet
