#include "render/gl/timer.h"

namespace planet {

GpuTimer::~GpuTimer() {
  for (auto& [pass, q] : pending_) free_.push_back(q);
  if (!free_.empty()) glDeleteQueries(GLsizei(free_.size()), free_.data());
}

void GpuTimer::begin(const std::string& pass) {
  GLuint q = 0;
  if (free_.empty()) {
    glCreateQueries(GL_TIME_ELAPSED, 1, &q);
  } else {
    q = free_.back();
    free_.pop_back();
  }
  pending_.emplace_back(pass, q);
  glBeginQuery(GL_TIME_ELAPSED, q);
}

void GpuTimer::end() { glEndQuery(GL_TIME_ELAPSED); }

std::vector<PassTiming> GpuTimer::collect() {
  std::vector<PassTiming> out;
  for (auto& [pass, q] : pending_) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
    out.push_back({pass, double(ns) * 1e-6});
    free_.push_back(q);
  }
  pending_.clear();
  return out;
}

}  // namespace planet
