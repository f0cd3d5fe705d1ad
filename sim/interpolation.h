#pragma once
// Monotone piecewise-cubic interpolation (Fritsch and Carlson 1980): C1
// through the keyframes and no overshoot between them, so a height that
// only climbs never dips below the ground between two keyframes.
#include <span>
#include <vector>

namespace planet {

class MonotoneCubic {
 public:
  MonotoneCubic() = default;
  // `t` strictly increasing, same length as `y`, at least one point.
  MonotoneCubic(std::vector<double> t, std::vector<double> y);

  double operator()(double t) const;
  double derivative(double t) const;
  // Prescribes the slope at knot i, where the curve must join another one
  // (an orbit) with its velocity: C1 is kept, monotonicity may not be.
  void set_slope(size_t i, double slope) { m_.at(i) = slope; }

 private:
  size_t segment(double t) const;
  std::vector<double> t_, y_, m_;
};

}  // namespace planet
