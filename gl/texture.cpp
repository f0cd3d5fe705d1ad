#include "gl/texture.h"

#include "core/error.h"
#include "gl/driver_watch.h"

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

Texture make_texture_3d(GLenum internal_format, int width, int height, int depth) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &id);
  glTextureStorage3D(id, 1, internal_format, width, height, depth);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  return Texture(id);
}

Texture make_texture_2d_multisample(GLenum internal_format, int samples, int width, int height) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
  glTextureStorage2DMultisample(id, samples, internal_format, width, height, GL_TRUE);
  return Texture(id);
}

Framebuffer make_framebuffer(GLuint color, GLuint depth, GLuint stencil) {
  return make_framebuffer({color}, depth, stencil);
}

Framebuffer make_framebuffer(std::initializer_list<GLuint> colors, GLuint depth, GLuint stencil) {
  GLuint fbo = 0;
  glCreateFramebuffers(1, &fbo);
  std::vector<GLenum> attachments;
  for (GLuint color : colors) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(attachments.size());
    glNamedFramebufferTexture(fbo, attachment, color, 0);
    attachments.push_back(attachment);
  }
  glNamedFramebufferDrawBuffers(fbo, GLsizei(attachments.size()), attachments.data());
  if (depth) glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth, 0);
  if (stencil) glNamedFramebufferTexture(fbo, GL_STENCIL_ATTACHMENT, stencil, 0);
  if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &fbo);
    throw SystemError("framebuffer incomplete");
  }
  return Framebuffer(fbo);
}

void begin_reversed_z(GLuint framebuffer, int width, int height, const float clear_color[4]) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  const float far_depth = 0.0f;
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, clear_color);
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &far_depth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
}

Buffer make_buffer(size_t bytes, const void* data, GLbitfield flags) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferStorage(id, GLsizeiptr(bytes), data, flags);
  return Buffer(id);
}

std::vector<float> read_texture_rgba32f(GLuint texture, int width, int height) {
  std::vector<float> pixels(size_t(width) * size_t(height) * 4);
  DriverWait wait("reading a float texture back");
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                    pixels.data());
  return pixels;
}

}  // namespace planet
