#include "lab/pareto.h"

#include <cstddef>

namespace planet {

std::vector<bool> pareto_front(const std::vector<CostError>& points) {
  std::vector<bool> on(points.size(), true);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = 0; j < points.size() && on[i]; ++j) {
      const CostError& a = points[j];
      const CostError& b = points[i];
      bool as_good = a.cost <= b.cost && a.error <= b.error;
      bool better = a.cost < b.cost || a.error < b.error;
      if (as_good && better) on[i] = false;
    }
  }
  return on;
}

}  // namespace planet
