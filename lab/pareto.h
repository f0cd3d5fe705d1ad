#pragma once
// The Pareto front of (cost, error) points: those that no other point
// beats on one without losing on the other. The lab's charts draw it.
#include <vector>

namespace planet {

struct CostError {
  double cost = 0;   // e.g. ms per frame
  double error = 0;  // e.g. relative RMSE
};

// Whether each point is on the front (minimising both). A point equal to
// another on both counts is on it if that one is; a dominated point (another
// as cheap and as accurate, and better on one) is not.
std::vector<bool> pareto_front(const std::vector<CostError>& points);

}  // namespace planet
