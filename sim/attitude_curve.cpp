#include "sim/attitude_curve.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace planet {

glm::dvec3 rotation_vector(const glm::dquat& q_in) {
  glm::dquat q = q_in.w < 0 ? -q_in : q_in;
  glm::dvec3 v(q.x, q.y, q.z);
  double s = glm::length(v);
  if (s < 1e-300) return glm::dvec3(0.0);
  double angle = 2.0 * std::atan2(s, q.w);
  return v * (angle / s);
}

glm::dquat from_rotation_vector(const glm::dvec3& v) {
  double angle = glm::length(v);
  if (angle < 1e-300) return glm::dquat(1, 0, 0, 0);
  glm::dvec3 axis = v / angle;
  double s = std::sin(0.5 * angle);
  return glm::dquat(std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s);
}

AttitudeCurve::AttitudeCurve(std::vector<double> t, std::vector<glm::dquat> q)
    : t_(std::move(t)), q_(std::move(q)), w_(t_.size(), glm::dvec3(0.0)) {
  assert(!t_.empty() && t_.size() == q_.size());
  const size_t n = t_.size();
  // Same hemisphere as the previous keyframe: the short way round.
  for (size_t i = 1; i < n; ++i) {
    if (glm::dot(q_[i], q_[i - 1]) < 0) q_[i] = -q_[i];
  }
  if (n < 2) return;
  // Angular velocity of each segment, in camera axes; the axis of the
  // relative rotation is the same seen from either end.
  std::vector<glm::dvec3> segment(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    segment[i] = rotation_vector(glm::inverse(q_[i]) * q_[i + 1]) / (t_[i + 1] - t_[i]);
  }
  w_[0] = segment[0];
  w_[n - 1] = segment[n - 2];
  for (size_t i = 1; i + 1 < n; ++i) {
    double h0 = t_[i] - t_[i - 1], h1 = t_[i + 1] - t_[i];
    // Carried into the frame of keyframe i: the previous segment's vector
    // is its own axis, unchanged by that segment's rotation.
    w_[i] = (h1 * segment[i - 1] + h0 * segment[i]) / (h0 + h1);
  }
}

glm::dquat AttitudeCurve::operator()(double t) const {
  if (t_.size() == 1 || t <= t_.front()) return q_.front();
  if (t >= t_.back()) return q_.back();
  auto it = std::upper_bound(t_.begin(), t_.end(), t);
  size_t i = std::min(size_t(it - t_.begin()) - 1, t_.size() - 2);
  if (t == t_[i]) return q_[i];
  double h = t_[i + 1] - t_[i];
  double s = (t - t_[i]) / h;
  // Bezier control points: q_i, q_i exp(w_i h/3), q_{i+1} exp(-w_{i+1} h/3),
  // q_{i+1}; their successive rotation vectors o1, o2, o3.
  glm::dquat p1 = q_[i] * from_rotation_vector(w_[i] * (h / 3.0));
  glm::dquat p2 = q_[i + 1] * from_rotation_vector(-w_[i + 1] * (h / 3.0));
  glm::dvec3 o1 = w_[i] * (h / 3.0);
  glm::dvec3 o2 = rotation_vector(glm::inverse(p1) * p2);
  glm::dvec3 o3 = w_[i + 1] * (h / 3.0);
  // Cumulative Bernstein basis of degree 3.
  double u = 1.0 - s;
  double b1 = 1.0 - u * u * u, b2 = 3.0 * s * s - 2.0 * s * s * s, b3 = s * s * s;
  return glm::normalize(q_[i] * from_rotation_vector(o1 * b1) * from_rotation_vector(o2 * b2) *
                        from_rotation_vector(o3 * b3));
}

glm::dvec3 AttitudeCurve::angular_velocity(double t) const {
  // Central difference of the curve itself, for checks and the HUD.
  const double dt = 1e-4;
  glm::dquat a = (*this)(t - dt), b = (*this)(t + dt);
  if (glm::dot(a, b) < 0) b = -b;
  return rotation_vector(glm::inverse(a) * b) / (2.0 * dt);
}

}  // namespace planet
