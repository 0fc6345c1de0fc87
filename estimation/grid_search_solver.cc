#include "estimation/grid_search_solver.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "estimation/alternation.h"

namespace corridor {
namespace {

class GridStageMinimizer : public StageMinimizer {
 public:
  explicit GridStageMinimizer(const GridSearchOptions& options) : options_(options) {}

  bool MinimizeSymmetry(const SymmetryResidual& residual, double x[2], double* cost,
                        int* evaluations) const override {
    return Minimize(residual, {options_.yaw_min, options_.yaw_max, options_.yaw_step},
                    {options_.offset_min, options_.offset_max, options_.offset_step}, x, cost,
                    evaluations);
  }

  bool MinimizeWidth(const WidthResidual& residual, double x[2], double* cost,
                     int* evaluations) const override {
    return Minimize(residual, {options_.pitch_min, options_.pitch_max, options_.pitch_step},
                    {options_.width_min, options_.width_max, options_.width_step}, x, cost,
                    evaluations);
  }

  // The first parameter found on the edge of its range, if any ("" when none): the true value
  // may lie outside what the grid covers, so the estimate is not to be trusted.
  const std::string& edge() const { return edge_; }

 private:
  template <typename Functor>
  bool Minimize(const Functor& functor, const GridAxis& a0, const GridAxis& a1, double x[2],
                double* cost, int* evaluations) const {
    std::vector<double> scratch;
    const auto evaluate = [&](const double p[2]) {
      return EvaluateStageCost(functor, p, options_.absolute_cost, &scratch);
    };
    *cost = GridMinimize2D(evaluate, a0, a1, options_.refinement_levels,
                           options_.refinement_factor, x, evaluations);
    const GridAxis* axes[2] = {&a0, &a1};
    for (int k = 0; k < 2 && edge_.empty(); ++k) {
      if (std::abs(x[k] - axes[k]->min) < 1e-9 || std::abs(x[k] - axes[k]->max) < 1e-9) {
        char text[128];
        std::snprintf(text, sizeof(text), "%g on the edge of [%g, %g]", x[k], axes[k]->min,
                      axes[k]->max);
        edge_ = text;
      }
    }
    return std::isfinite(*cost);
  }

  const GridSearchOptions options_;
  mutable std::string edge_;  // One minimiser serves one Solve call.
};

}  // namespace

Status GridSearchSolver::Solve(const CorridorObservation& observation,
                               const CorridorGeometry* initial, SolverSummary* summary) const {
  const auto start = std::chrono::steady_clock::now();
  *summary = SolverSummary();
  summary->solver_name = Name();
  const GridStageMinimizer minimizer(options_.grid);
  Status status = RunAlternation(observation, initial, options_, minimizer, summary);
  if (status.ok() && !minimizer.edge().empty()) {
    status = Status::ImplausibleGeometry("grid search: best value " + minimizer.edge() +
                                         " of its range; the corridor lies outside the grid");
  }
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

}  // namespace corridor
