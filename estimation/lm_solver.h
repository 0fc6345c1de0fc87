#pragma once

#include "corridor_depth/solver.h"

namespace corridor {

// Ceres Levenberg-Marquardt on the same SymmetryResidual and WidthResidual functors (autodiff),
// inside the paper's stage alternation, with an optional robust loss and bounds on the angles.
// Without an initial estimate it starts from the closed form's (LmOptions::start_from_closed_form).
// Each stage's robust loss is scaled to its residuals (SolverOptions::loss_sigmas), and points far
// from the fit's junction lines are dropped and the alternation rerun, as in "joint"
// (SolverOptions::trim_sigmas).
class LmSolver : public CorridorSolver {
 public:
  explicit LmSolver(const SolverOptions& options) : options_(options) {}
  std::string Name() const override { return "lm"; }
  Status Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
               SolverSummary* summary) const override;

 private:
  // Refits *summary's estimate on the points within trim_sigmas of its lines, until they repeat.
  void TrimAndRefit(const CorridorObservation& observation, SolverSummary* summary) const;

  const SolverOptions options_;
};

}  // namespace corridor
