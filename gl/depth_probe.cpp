#include "gl/depth_probe.h"

#include "gl/driver_watch.h"

namespace planet {

DepthProbe::DepthProbe()
    : program_(Program::graphics("gl/shaders/fullscreen.vert", "gl/shaders/depth_probe.frag")) {
  glCreateQueries(GL_ANY_SAMPLES_PASSED, 1, &query_);
  note_gl_objects(GlObjectKind::query, 1);
}

DepthProbe::~DepthProbe() {
  glDeleteQueries(1, &query_);
  note_gl_objects(GlObjectKind::query, -1);
}

bool DepthProbe::any_nearer(GLuint depth_texture, int width, int height, float near,
                            float view_depth) {
  if (view_depth <= near) return false;
  if (attached_ != depth_texture) {
    framebuffer_ = make_framebuffer(0, depth_texture);
    attached_ = depth_texture;
  }
  pass_.begin(framebuffer_.id(), width, height, program_);
  // A fragment at the probe's depth passes where the stored depth is at
  // least as great: where a surface lies at or nearer than view_depth.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glUniform1f(program_.uniform("u_depth"), near / view_depth);
  glBeginQuery(GL_ANY_SAMPLES_PASSED, query_);
  pass_.draw();
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  GLuint any = 0;
  DriverWait wait("waiting for a depth probe's answer");
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &any);
  return any != 0;
}

}  // namespace planet
