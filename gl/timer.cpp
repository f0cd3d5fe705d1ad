#include "gl/timer.h"

#include "gl/driver_watch.h"
#include "gl/live_objects.h"

#include <algorithm>

namespace planet {

GpuTimer::~GpuTimer() {
  if (group_open_) glPopDebugGroup();
  for (auto& p : pending_) {
    if (!p.reused && !p.on_cpu && !p.skipped) free_.push_back(p.query);
  }
  if (free_.empty()) return;
  glDeleteQueries(GLsizei(free_.size()), free_.data());
  note_gl_objects(GlObjectKind::query, -long(free_.size()));
}

void GpuTimer::begin(const std::string& pass) {
  GLuint q = 0;
  if (free_.empty()) {
    glCreateQueries(GL_TIME_ELAPSED, 1, &q);
    note_gl_objects(GlObjectKind::query, 1);
  } else {
    q = free_.back();
    free_.pop_back();
  }
  if (synchronous_) {
    DriverWait wait("finishing the passes before a timed one");
    glFinish();
  }
  pending_.push_back({pass, q, std::chrono::steady_clock::now()});
  // A pass that threw left its group open: it closes here, so that the
  // groups never pile up past the GL's limit (64).
  if (group_open_) glPopDebugGroup();
  // A debug group per pass: a GL error reported within it names the pass
  // (gl/debug_output.h), and GL debuggers show the frame's passes by name.
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, pass.c_str());
  group_open_ = true;
  glBeginQuery(GL_TIME_ELAPSED, q);
}

void GpuTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  if (group_open_) glPopDebugGroup();
  group_open_ = false;
  if (!synchronous_) return;
  {
    DriverWait wait("finishing a timed pass");
    glFinish();
  }
  Pending& p = pending_.back();
  p.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - p.begun).count();
}

void GpuTimer::reuse(const std::string& pass) {
  Pending p{pass, 0, std::chrono::steady_clock::now()};
  p.reused = true;
  pending_.push_back(p);
}

void GpuTimer::skip(const std::string& pass) {
  Pending p{pass, 0, std::chrono::steady_clock::now()};
  p.skipped = true;
  pending_.push_back(p);
}

void GpuTimer::cpu(const std::string& pass, double ms) {
  Pending p{pass, 0, std::chrono::steady_clock::now()};
  p.on_cpu = true;
  p.wall_ms = ms;
  pending_.push_back(p);
}

std::vector<PassTiming> GpuTimer::collect() {
  std::vector<PassTiming> out;
  for (auto& p : pending_) {
    if (p.reused || p.skipped) {
      PassTiming t{p.pass};
      t.reused = p.reused;
      t.skipped = p.skipped;
      out.push_back(t);
      continue;
    }
    if (p.on_cpu) {
      out.push_back({p.pass, p.wall_ms, p.wall_ms, false, true});
      continue;
    }
    GLuint64 ns = 0;
    DriverWait wait("waiting for a pass's GPU time");
    glGetQueryObjectui64v(p.query, GL_QUERY_RESULT, &ns);
    // A pass cannot take longer than the wall time from its begin() to now.
    // Mesa's llvmpipe reports the first draw-carrying query of a context as
    // the time since an arbitrary epoch (about 15 minutes here); this
    // bound turns that into an honest upper limit.
    double wall_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - p.begun)
            .count();
    out.push_back({p.pass, std::min(double(ns) * 1e-6, wall_ms), p.wall_ms});
    free_.push_back(p.query);
  }
  pending_.clear();
  return out;
}

}  // namespace planet
