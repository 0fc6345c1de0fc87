#pragma once

// Template definitions of the grid searches declared in grid_search_solver.h.

#include <algorithm>
#include <cmath>
#include <limits>

namespace corridor {

template <typename CostFn>
double GridMinimize1D(const CostFn& cost, const GridAxis& axis, int levels, double factor,
                      double* x, int* evaluations) {
  double best = std::numeric_limits<double>::infinity();
  GridAxis range = axis;
  for (int level = 0; level <= levels; ++level) {
    const int n = static_cast<int>(std::floor((range.max - range.min) / range.step + 1e-9));
    for (int i = 0; i <= n; ++i) {
      const double value = range.min + i * range.step;
      const double c = cost(value);
      ++*evaluations;
      if (c < best) {
        best = c;
        *x = value;
      }
    }
    if (!std::isfinite(best)) return best;
    range = {std::max(axis.min, *x - range.step), std::min(axis.max, *x + range.step),
             range.step / factor};
  }
  return best;
}

template <typename CostFn>
double GridMinimize2D(const CostFn& cost, const GridAxis& outer, const GridAxis& inner,
                      int levels, double factor, double x[2], int* evaluations) {
  double inner_best = x[1];
  const auto profile = [&](double outer_value) {
    double inner_x = inner.min;
    const double c = GridMinimize1D(
        [&](double inner_value) {
          const double p[2] = {outer_value, inner_value};
          return cost(p);
        },
        inner, levels, factor, &inner_x, evaluations);
    return c;
  };
  double outer_best = x[0];
  const double best = GridMinimize1D(profile, outer, levels, factor, &outer_best, evaluations);
  if (!std::isfinite(best)) return best;
  // Recover the inner argument at the best outer value.
  GridMinimize1D(
      [&](double inner_value) {
        const double p[2] = {outer_best, inner_value};
        return cost(p);
      },
      inner, levels, factor, &inner_best, evaluations);
  x[0] = outer_best;
  x[1] = inner_best;
  return best;
}

}  // namespace corridor
