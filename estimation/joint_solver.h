#pragma once

#include "corridor_depth/solver.h"

namespace corridor {

// "joint" (beyond the paper): one Levenberg-Marquardt problem over yaw, pitch, offset and width,
// with a JunctionLineResidual per edge point and the robust loss per point, solved by
// SolveBoundedLm (the steps of Ceres's LM, without allocating). Starts from `initial` when given,
// else from the closed-form solution.
class JointSolver : public CorridorSolver {
 public:
  explicit JointSolver(const SolverOptions& options) : options_(options) {}
  std::string Name() const override { return "joint"; }
  Status Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
               SolverSummary* summary) const override;

 private:
  const SolverOptions options_;
};

}  // namespace corridor
