#pragma once
// Shortest paths along a body's ellipsoid (geodesics, Karney 2013,
// "Algorithms for geodesics", through GeographicLib::Geodesic): distances
// and headings for flight planning.
#include "sim/body.h"
#include "sim/geodesy.h"

#include <memory>

namespace GeographicLib {
class Geodesic;
}

namespace planet {

struct SurfaceLine {
  double distance = 0;       // metres along the ellipsoid
  double start_heading = 0;  // radians clockwise from north, at the start
  double end_heading = 0;    // at the end, in the direction of travel
};

class Geodesics {
 public:
  explicit Geodesics(const Ellipsoid& shape);
  ~Geodesics();
  // The shortest line between two places (heights are ignored).
  SurfaceLine between(const Geodetic& from, const Geodetic& to) const;
  // Where a line leaving `from` at `heading` arrives after `distance`;
  // the height is kept.
  Geodetic travel(const Geodetic& from, double heading, double distance) const;

 private:
  std::unique_ptr<GeographicLib::Geodesic> geodesic_;
};

}  // namespace planet
