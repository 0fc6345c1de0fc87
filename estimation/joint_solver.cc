#include "estimation/joint_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "estimation/bounded_lm.h"
#include "estimation/capped_weights.h"
#include "estimation/closed_form.h"
#include "estimation/junction_residuals.h"
#include "estimation/junction_trim.h"

namespace corridor {
namespace {

// The loss for a solve starting at x: of scale options.loss_sigmas robust standard deviations of
// the points' distances there, both sides pooled (at least kMinSigmaPx, a guard for points without
// spread), or of the fixed options.loss_scale.
RobustLoss LossAt(const SolverOptions& options, const CorridorObservation& observation,
                  const FloorIntrinsics& intrinsics, const double x[4]) {
  double sigma = 0;
  if (options.loss_sigmas > 0 && RobustSigma(observation, intrinsics, x, 0, &sigma)) {
    return RobustLoss::FromName(options.loss, options.loss_sigmas * std::max(sigma, kMinSigmaPx));
  }
  return RobustLoss::FromName(options.loss, options.loss_scale);
}

}  // namespace

Status JointSolver::Solve(const CorridorObservation& given, const CorridorGeometry* initial,
                          SolverSummary* summary) const {
  const auto start = std::chrono::steady_clock::now();
  *summary = SolverSummary();
  summary->solver_name = Name();
  std::string why;
  if (!given.Check(&why)) return Status::InvalidArgument(why);
  // The points with their weights capped; the thread's, reused from call to call.
  thread_local CorridorObservation capped;
  const CorridorObservation& observation =
      CapWeights(given, options_.max_weight_ratio, &capped) ? capped : given;
  CorridorGeometry start_geometry;
  if (initial != nullptr) {
    start_geometry = *initial;
  } else {
    const Status status = SolveClosedForm(observation, &start_geometry);
    if (!status.ok()) return status;
  }
  const LmOptions& lm = options_.lm;
  double x[4] = {std::clamp(start_geometry.yaw, -lm.max_abs_yaw, lm.max_abs_yaw),
                 std::clamp(start_geometry.pitch, -lm.max_abs_pitch, lm.max_abs_pitch),
                 start_geometry.offset,
                 start_geometry.width > 0.05 ? start_geometry.width : lm.initial_width};
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double lower[4] = {-lm.max_abs_yaw, -lm.max_abs_pitch, -kInf, 0.05};
  const double upper[4] = {lm.max_abs_yaw, lm.max_abs_pitch, kInf, kInf};
  BoundedLmOptions lm_options;
  lm_options.max_iterations = lm.max_iterations;
  lm_options.function_tolerance = lm.function_tolerance;
  lm_options.parameter_tolerance = lm.parameter_tolerance;
  lm_options.gradient_tolerance = lm.gradient_tolerance;
  const FloorIntrinsics intrinsics{observation.fx, observation.fy, observation.cx, observation.cy,
                                   observation.camera_height};
  lm_options.loss = LossAt(options_, observation, intrinsics, x);
  BoundedLmSummary lm_summary =
      SolveBoundedLm<4>(JunctionResiduals(observation, intrinsics), lm_options, lower, upper, x);
  summary->evaluations = lm_summary.residual_evaluations;
  summary->iterations = lm_summary.iterations;
  // Trimming: refit on the points near the fit's lines, which are chosen again from all points at
  // each new fit (a point dropped by a fit pulled off by others may come back), until they repeat.
  // The thread's, reused from call to call.
  TrimBuffers& buffers = ThreadTrimBuffers(observation.left.size() + observation.right.size());
  CorridorObservation& kept = buffers.kept;
  std::vector<char>& mask = buffers.mask;
  std::vector<char>& previous = buffers.previous;
  constexpr int kMaxTrimRounds = 3;
  for (int round = 0; options_.trim_sigmas > 0 && round < kMaxTrimRounds &&
                      lm_summary.termination != BoundedLmSummary::Termination::kFailure;
       ++round) {
    if (!TrimToFit(observation, intrinsics, x, options_.trim_sigmas, &kept, &mask) ||
        mask == previous) {
      break;
    }
    previous.swap(mask);
    double refit[4] = {x[0], x[1], x[2], x[3]};
    lm_options.loss = LossAt(options_, observation, intrinsics, x);
    const BoundedLmSummary trimmed =
        SolveBoundedLm<4>(JunctionResiduals(kept, intrinsics), lm_options, lower, upper, refit);
    summary->evaluations += trimmed.residual_evaluations;
    summary->iterations += trimmed.iterations;
    if (trimmed.termination == BoundedLmSummary::Termination::kFailure) break;
    lm_summary = trimmed;
    std::copy(refit, refit + 4, x);
  }
  summary->final_cost = lm_summary.final_cost;
  summary->converged = lm_summary.termination == BoundedLmSummary::Termination::kConvergence;
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (lm_summary.termination == BoundedLmSummary::Termination::kFailure) {
    return Status::ImplausibleGeometry(std::string("joint solve failed: ") + lm_summary.message);
  }
  summary->estimate.yaw = x[0];
  summary->estimate.pitch = x[1];
  summary->estimate.offset = x[2];
  summary->estimate.width = x[3];
  summary->estimate.camera_height = observation.camera_height;
  return Status::Ok();
}

}  // namespace corridor
