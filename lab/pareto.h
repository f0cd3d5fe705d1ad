#pragma once
// The Pareto front of (cost, error) points: those that no other point
// beats on one without losing on the other. The lab's charts draw it.
// Measured counts are noisy: two costs whose spreads, each centred on its
// cost, overlap, or two errors whose intervals overlap, tie, and a tie
// beats neither.
#include <cstddef>
#include <vector>

namespace planet {

struct CostError {
  double cost = 0;         // e.g. ms per frame
  double error = 0;        // e.g. relative RMSE
  double cost_spread = 0;  // how far the cost's measurements spread (max - min); 0: exact
  // The error's interval (e.g. 95 %) where error_high > error_low; else
  // the error alone.
  double error_low = 0, error_high = 0;
};

// Whether two costs tie: their spreads, each centred on its cost, overlap
// (they differ by no more than half the sum of the spreads).
bool costs_tie(const CostError& a, const CostError& b);
// Whether two errors tie: their intervals overlap (an error without one is
// a point), or they are equal.
bool errors_tie(const CostError& a, const CostError& b);

// Whether each point is on the front (minimising both). A point is off it
// where another is as cheap and as accurate, each within the noise, and
// better beyond the noise on one: points that tie on both counts are on
// it or off it together, and equal points too.
std::vector<bool> pareto_front(const std::vector<CostError>& points);

// For each point, the others whose cost ties with its own, in order.
std::vector<std::vector<size_t>> cost_ties(const std::vector<CostError>& points);

}  // namespace planet
