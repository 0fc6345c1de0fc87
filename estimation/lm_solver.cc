#include "estimation/lm_solver.h"

#include <chrono>
#include <vector>

#include <ceres/ceres.h>

#include "estimation/alternation.h"
#include "estimation/capped_weights.h"
#include "estimation/closed_form.h"
#include "estimation/junction_trim.h"
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

Status LmSolver::Solve(const CorridorObservation& given, const CorridorGeometry* initial,
                       SolverSummary* summary) const {
  const auto start = std::chrono::steady_clock::now();
  *summary = SolverSummary();
  summary->solver_name = Name();
  // The points with their weights capped; the thread's, reused from call to call.
  thread_local CorridorObservation capped;
  const CorridorObservation& observation =
      CapWeights(given, options_.max_weight_ratio, &capped) ? capped : given;
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
                            summary, /*scale_loss_to_residuals=*/true);
    solved = status.ok();
  }
  if (!solved) {
    const int evaluations = summary->evaluations;
    *summary = SolverSummary();
    summary->solver_name = Name();
    status = RunAlternation(observation, initial, options_, LmStageMinimizer(options_.lm), summary,
                            /*scale_loss_to_residuals=*/true);
    summary->evaluations += evaluations;
  }
  if (status.ok()) TrimAndRefit(observation, summary);
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

void LmSolver::TrimAndRefit(const CorridorObservation& observation, SolverSummary* summary) const {
  // As the joint solver: refit on the points near the fit's junction lines, chosen again from all
  // points at each new fit, until they repeat. A point is judged by its distance from its line in
  // the image, which neither stage's residual alone measures. The thread's, reused from call to
  // call.
  TrimBuffers& buffers = ThreadTrimBuffers(observation.left.size() + observation.right.size());
  CorridorObservation& kept = buffers.kept;
  std::vector<char>& mask = buffers.mask;
  std::vector<char>& previous = buffers.previous;
  const FloorIntrinsics intrinsics{observation.fx, observation.fy, observation.cx, observation.cy,
                                   observation.camera_height};
  constexpr int kMaxTrimRounds = 3;
  for (int round = 0; options_.trim_sigmas > 0 && round < kMaxTrimRounds; ++round) {
    const CorridorGeometry fit = summary->estimate;
    const double x[4] = {fit.yaw, fit.pitch, fit.offset, fit.width};
    if (!TrimToFit(observation, intrinsics, x, options_.trim_sigmas, &kept, &mask) ||
        mask == previous) {
      break;
    }
    previous.swap(mask);
    SolverSummary refit;
    if (!RunAlternation(kept, &fit, options_, LmStageMinimizer(options_.lm), &refit,
                        /*scale_loss_to_residuals=*/true)
             .ok()) {
      break;
    }
    refit.evaluations += summary->evaluations;
    refit.iterations += summary->iterations;
    refit.solver_name = summary->solver_name;
    *summary = refit;
  }
}

}  // namespace corridor
