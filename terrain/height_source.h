#pragma once
// Where terrain heights come from. A height source answers two questions
// about the surface, in the body frame: how high the ground stands above
// the body's base shape along a direction, and within which heights the
// ground stays over a patch, which culling and level of detail need before
// any tile of that patch has been built.
#include <glm/glm.hpp>

#include <memory>

namespace planet {

struct HeightRange {
  double min = 0, max = 0;  // metres above the base shape
};

// Where a point lies on the ground a crater marks, each share in [0, 1]:
// its floor, its raised rim, and its ejecta blanket (streaked into rays
// around the young craters). The rim and the ejecta fade with a crater's
// age, the floor does not. A body's palette turns them into brightness.
struct CraterMarks {
  double floor = 0, rim = 0, ejecta = 0;
};

class HeightSource {
 public:
  virtual ~HeightSource() = default;

  // Height above the base shape, metres, along the unit direction dir_body.
  // Safe to call from several threads at once.
  virtual double height(const glm::dvec3& dir_body) const = 0;

  // Heights everywhere within `radius` metres (measured on the surface)
  // of the direction; conservative (may be wider than the truth).
  virtual HeightRange range_near(const glm::dvec3& dir_body, double radius) const = 0;

  // Heights anywhere on the body.
  virtual HeightRange range() const = 0;

  // An upper bound on how far the surface leaves a linear interpolation of
  // samples spaced `spacing` metres apart: the geometric error of a tile
  // grid of that cell size, which level of detail projects to the screen.
  virtual double interpolation_error(double spacing) const = 0;

  // The ground's height along a direction as if no sea filled it: under a
  // sea, its floor, where height() gives the sea's surface.
  virtual double seabed_height(const glm::dvec3& dir_body) const { return height(dir_body); }

  // The marks of the craters at a direction, of those wide enough to show
  // on samples spaced `spacing` metres apart (finer ones would alias into
  // specks); none where the source has no craters.
  virtual CraterMarks crater_marks(const glm::dvec3& dir_body, double spacing) const {
    (void)dir_body, (void)spacing;
    return {};
  }
};

}  // namespace planet
