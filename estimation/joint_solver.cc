#include "estimation/joint_solver.h"

#include <algorithm>
#include <chrono>

#include "estimation/bounded_lm.h"
#include "estimation/closed_form.h"
#include "estimation/junction_line_residual.h"

namespace corridor {
namespace {

// The JunctionLineResidual of every edge point: the left junction's points, then the right's.
struct JunctionResiduals {
  const CorridorObservation& observation;
  const FloorIntrinsics intrinsics;

  int size() const { return static_cast<int>(observation.left.size() + observation.right.size()); }

  template <typename T>
  bool operator()(int i, const T* x, T* residual) const {
    const int left = static_cast<int>(observation.left.size());
    const auto& p = i < left ? observation.left[i] : observation.right[i - left];
    return JunctionLineResidual(intrinsics, p.x(), p.y(), i < left ? -1 : 1)(x, residual);
  }
};

}  // namespace

Status JointSolver::Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
                          SolverSummary* summary) const {
  const auto start = std::chrono::steady_clock::now();
  *summary = SolverSummary();
  summary->solver_name = Name();
  std::string why;
  if (!observation.Check(&why)) return Status::InvalidArgument(why);
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
  lm_options.loss = RobustLoss::FromName(options_.loss, options_.loss_scale);
  const JunctionResiduals residuals{
      observation, FloorIntrinsics{observation.fx, observation.fy, observation.cx,
                                   observation.cy, observation.camera_height}};
  const BoundedLmSummary lm_summary = SolveBoundedLm<4>(residuals, lm_options, lower, upper, x);
  summary->evaluations = lm_summary.residual_evaluations;
  summary->iterations = lm_summary.iterations;
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
