#pragma once
// Attitude through keyframes as a C1 curve of unit quaternions: a cubic
// Bezier curve in the cumulative form of Kim, Kim and Shin (1995), "A
// general construction scheme for unit quaternion curves with simple high
// order derivatives" (SIGGRAPH), with angular velocities at the keyframes
// estimated from the neighbours (a Catmull-Rom choice weighted for uneven
// keyframe spacing). Quaternions have no gimbal: nothing flips at a pole
// or when looking straight down.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace planet {

class AttitudeCurve {
 public:
  AttitudeCurve() = default;
  // `t` strictly increasing; each q maps camera axes into body axes.
  AttitudeCurve(std::vector<double> t, std::vector<glm::dquat> q);

  glm::dquat operator()(double t) const;
  // Angular velocity in camera axes, radians per second.
  glm::dvec3 angular_velocity(double t) const;

 private:
  std::vector<double> t_;
  std::vector<glm::dquat> q_;
  std::vector<glm::dvec3> w_;  // angular velocity at each keyframe, camera axes
};

// The rotation vector (axis times angle) of a unit quaternion, angle in [0, pi].
glm::dvec3 rotation_vector(const glm::dquat& q);
glm::dquat from_rotation_vector(const glm::dvec3& v);

}  // namespace planet
