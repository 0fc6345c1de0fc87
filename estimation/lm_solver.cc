#include "estimation/lm_solver.h"

#include <chrono>

#include <ceres/ceres.h>

#include "estimation/alternation.h"
#include "estimation/closed_form.h"
#include "estimation/ceres_options.h"

namespace corridor {
namespace {

class LmStageMinimizer : public StageMinimizer {
 public:
  explicit LmStageMinimizer(const LmOptions& options) : options_(options) {}

  bool MinimizeSymmetry(const SymmetryResidual& residual, double x[2], double* cost,
                        int* evaluations) const override {
    auto* functor = new SymmetryResidual(residual);
    auto* cost_function = new ceres::AutoDiffCostFunction<SymmetryResidual, ceres::DYNAMIC, 2>(
        functor, functor->NumResiduals());
    return Minimize(cost_function, options_.max_abs_yaw, {-1e3, 1e3}, x, cost, evaluations);
  }

  bool MinimizeWidth(const WidthResidual& residual, double x[2], double* cost,
                     int* evaluations) const override {
    auto* functor = new WidthResidual(residual);
    auto* cost_function = new ceres::AutoDiffCostFunction<WidthResidual, ceres::DYNAMIC, 2>(
        functor, functor->NumResiduals());
    return Minimize(cost_function, options_.max_abs_pitch, {0.05, 1e3}, x, cost, evaluations);
  }

 private:
  struct Bounds {
    double lower, upper;  // Bounds on the second parameter.
  };

  bool Minimize(ceres::CostFunction* cost_function, double max_abs_angle, Bounds second,
                double x[2], double* cost, int* evaluations) const {
    x[0] = std::clamp(x[0], -max_abs_angle, max_abs_angle);
    x[1] = std::clamp(x[1], second.lower, second.upper);
    ceres::Problem problem;
    problem.AddResidualBlock(cost_function, nullptr, x);  // The functors hold the loss.
    problem.SetParameterLowerBound(x, 0, -max_abs_angle);
    problem.SetParameterUpperBound(x, 0, max_abs_angle);
    problem.SetParameterLowerBound(x, 1, second.lower);
    problem.SetParameterUpperBound(x, 1, second.upper);
    ceres::Solver::Summary summary;
    ceres::Solve(LevenbergMarquardtOptions(options_), &problem, &summary);
    *evaluations += summary.num_residual_evaluations;
    *cost = summary.final_cost;
    return summary.IsSolutionUsable() && std::isfinite(summary.final_cost);
  }

  const LmOptions options_;
};

}  // namespace

Status LmSolver::Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
                       SolverSummary* summary) const {
  const auto start = std::chrono::steady_clock::now();
  *summary = SolverSummary();
  summary->solver_name = Name();
  // Without an initial estimate, the closed form's (when it has one): the alternation from zero
  // yaw and offset and a guessed width can stop in another minimum. The closed form is not
  // robust: where gross outliers put its estimate where the stages find no floor, the
  // alternation's own start.
  CorridorGeometry closed_form;
  Status status;
  bool solved = false;
  if (initial == nullptr && options_.lm.start_from_closed_form &&
      SolveClosedForm(observation, &closed_form).ok()) {
    status = RunAlternation(observation, &closed_form, options_, LmStageMinimizer(options_.lm),
                            summary);
    solved = status.ok();
  }
  if (!solved) {
    const int evaluations = summary->evaluations;
    *summary = SolverSummary();
    summary->solver_name = Name();
    status = RunAlternation(observation, initial, options_, LmStageMinimizer(options_.lm), summary);
    summary->evaluations += evaluations;
  }
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

}  // namespace corridor
