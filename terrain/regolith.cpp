#include "terrain/regolith.h"

#include <glm/glm.hpp>

#include <cmath>

namespace planet {

// The shader's names in a namespace of their own: the library compiles as
// one unity source in some builds, where kPi is another file's too.
namespace regolith_shader {

using namespace glm;
using Real = double;
constexpr Real kPi = 3.14159265358979323846;
#include "terrain/shaders/regolith.glsl"

}  // namespace regolith_shader

namespace {

using regolith_shader::RegolithLaw;

RegolithLaw law_of(const Regolith& r) { return RegolithLaw{r.w, r.xi, r.b0, r.h, r.theta_bar}; }

}  // namespace

double regolith_reflectance(const Regolith& regolith, double mu0, double mu, double cos_g) {
  return regolith_shader::regolith_reflectance(law_of(regolith), mu0, mu, cos_g);
}

double regolith_normal_albedo(const Regolith& regolith) {
  return regolith_shader::kPi *
         regolith_shader::regolith_reflectance(law_of(regolith), 1.0, 1.0, 1.0);
}

double regolith_disk_brightness(const Regolith& regolith, double phase) {
  // The eye on +z, the sun at `phase` from it in the x-z plane; the point
  // of the sphere at polar angle t from the disk's centre and azimuth a
  // covers sin t cos t dt da of the disk (midpoints in t and a).
  constexpr double pi = regolith_shader::kPi;
  const RegolithLaw law = law_of(regolith);
  const glm::dvec3 sun(std::sin(phase), 0.0, std::cos(phase));
  const double cos_g = std::cos(phase);
  constexpr int kPolar = 400, kAzimuth = 800;
  double sum = 0;
  for (int j = 0; j < kPolar; ++j) {
    double t = (j + 0.5) * (0.5 * pi / kPolar);
    double ring = 0;
    for (int k = 0; k < kAzimuth; ++k) {
      double a = (k + 0.5) * (2.0 * pi / kAzimuth);
      glm::dvec3 n(std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t));
      ring += regolith_shader::regolith_reflectance(law, glm::dot(n, sun), n.z, cos_g);
    }
    sum += ring * std::sin(t) * std::cos(t);
  }
  return sum * (0.5 * pi / kPolar) * (2.0 * pi / kAzimuth);
}

}  // namespace planet
