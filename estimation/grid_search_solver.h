#pragma once

#include "corridor_depth/solver.h"

namespace corridor {

// The paper's solver: each stage is an exhaustive search over a 2D grid of its two parameters
// (III-B: yaw in [-0.314, 0.314]; III-C: pitch in [lambda_1, lambda_2]), evaluating the very
// same functors as Ceres does, followed by optional coarse-to-fine refinement around the best
// cell, inside the paper's stage alternation.
class GridSearchSolver : public CorridorSolver {
 public:
  explicit GridSearchSolver(const SolverOptions& options) : options_(options) {}
  std::string Name() const override { return "grid"; }
  Status Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
               SolverSummary* summary) const override;

 private:
  const SolverOptions options_;
};

// One axis of a search grid.
struct GridAxis {
  double min, max, step;  // Inclusive range and step.
};

// Exhaustive 1D search of cost(x) over the axis, then `levels` refinements that shrink the step
// by `factor` within one step of the best value. Returns the best cost (+infinity when every
// value was rejected) and writes the best x.
template <typename CostFn>
double GridMinimize1D(const CostFn& cost, const GridAxis& axis, int levels, double factor,
                      double* x, int* evaluations);

// Exhaustive 2D search over (outer, inner) as a profile: for each outer value (an angle), the
// best inner value (offset or width, in which each stage's residual is affine, so the profile
// is exact) by GridMinimize1D; then the same over the outer axis. A plain 2D coarse-to-fine box
// would lose the truth in the long diagonal valley that couples yaw with offset.
template <typename CostFn>
double GridMinimize2D(const CostFn& cost, const GridAxis& outer, const GridAxis& inner,
                      int levels, double factor, double x[2], int* evaluations);

}  // namespace corridor

#include "estimation/grid_search_impl.h"
