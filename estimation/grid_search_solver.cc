#include "estimation/grid_search_solver.h"

#include <chrono>

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
    return std::isfinite(*cost);
  }

  const GridSearchOptions options_;
};

}  // namespace

Status GridSearchSolver::Solve(const CorridorObservation& observation,
                               const CorridorGeometry* initial, SolverSummary* summary) const {
  const auto start = std::chrono::steady_clock::now();
  *summary = SolverSummary();
  summary->solver_name = Name();
  const Status status =
      RunAlternation(observation, initial, options_, GridStageMinimizer(options_.grid), summary);
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

}  // namespace corridor
