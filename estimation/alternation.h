#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "corridor_depth/status.h"
#include "corridor_depth/corridor_observation.h"
#include "corridor_depth/solver.h"
#include "corridor_depth/symmetry_residual.h"
#include "corridor_depth/width_residual.h"

namespace corridor {

// Minimises one stage functor over its two parameters, in place. Implemented by the grid search
// and by Levenberg-Marquardt, so that the paper's alternation is written once.
class StageMinimizer {
 public:
  virtual ~StageMinimizer() = default;
  // x = (yaw, offset) on entry (start) and exit (best). Returns false when no valid point exists.
  virtual bool MinimizeSymmetry(const SymmetryResidual& residual, double x[2], double* cost,
                                int* evaluations) const = 0;
  // x = (pitch, width).
  virtual bool MinimizeWidth(const WidthResidual& residual, double x[2], double* cost,
                             int* evaluations) const = 0;
};

// The paper's alternation (docs/geometry.md, section 5): start from `initial` (or the options'
// pitch prior), solve stage 1 (yaw, offset), then stage 2 (pitch, width), until nothing moves.
// With scale_loss_to_residuals, each stage's loss has the scale of options.loss_sigmas robust
// standard deviations of that stage's residuals at its start (SolverOptions::loss_sigmas); else
// the fixed options.loss_scale.
Status RunAlternation(const CorridorObservation& observation, const CorridorGeometry* initial,
                      const SolverOptions& options, const StageMinimizer& minimizer,
                      SolverSummary* summary, bool scale_loss_to_residuals = false);

// Evaluates a stage functor at x; +infinity when the functor rejects x.
template <typename Functor>
double EvaluateStageCost(const Functor& functor, const double x[2], bool absolute,
                         std::vector<double>* scratch) {
  scratch->resize(functor.NumResiduals());
  if (!functor(x, scratch->data())) return std::numeric_limits<double>::infinity();
  double cost = 0;
  for (double r : *scratch) cost += absolute ? std::abs(r) : 0.5 * r * r;
  return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
}

}  // namespace corridor
