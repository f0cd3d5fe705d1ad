#include "lab/pareto.h"

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

bool has_error_interval(const CostError& p) { return p.error_high > p.error_low; }
double error_low_of(const CostError& p) { return has_error_interval(p) ? p.error_low : p.error; }
double error_high_of(const CostError& p) { return has_error_interval(p) ? p.error_high : p.error; }

// Whether `a` beats `b`: as cheap and as accurate within the noise, and
// better beyond it on one.
bool dominates(const CostError& a, const CostError& b) {
  bool cost_tie = costs_tie(a, b), error_tie = errors_tie(a, b);
  bool as_good = (a.cost <= b.cost || cost_tie) && (a.error <= b.error || error_tie);
  bool better = (a.cost < b.cost && !cost_tie) || (a.error < b.error && !error_tie);
  return as_good && better;
}

}  // namespace

bool costs_tie(const CostError& a, const CostError& b) {
  return std::abs(a.cost - b.cost) <= 0.5 * (a.cost_spread + b.cost_spread);
}

bool errors_tie(const CostError& a, const CostError& b) {
  return a.error == b.error ||
         (error_low_of(a) <= error_high_of(b) && error_low_of(b) <= error_high_of(a));
}

std::vector<bool> pareto_front(const std::vector<CostError>& points) {
  std::vector<bool> on(points.size(), true);
  for (size_t i = 0; i < points.size(); ++i) {
    for (size_t j = 0; j < points.size() && on[i]; ++j) {
      if (j != i && dominates(points[j], points[i])) on[i] = false;
    }
  }
  return on;
}

std::vector<std::vector<size_t>> cost_ties(const std::vector<CostError>& points) {
  std::vector<std::vector<size_t>> ties(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    for (size_t j = 0; j < points.size(); ++j) {
      if (j != i && costs_tie(points[i], points[j])) ties[i].push_back(j);
    }
  }
  return ties;
}

}  // namespace planet
