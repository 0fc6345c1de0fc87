#include "estimation/joint_solver.h"

#include <algorithm>
#include <chrono>

#include <ceres/ceres.h>

#include "estimation/ceres_options.h"
#include "estimation/closed_form.h"
#include "estimation/junction_line_residual.h"

namespace corridor {
namespace {

ceres::LossFunction* MakeLoss(const SolverOptions& options) {
  if (options.loss == "huber") return new ceres::HuberLoss(options.loss_scale);
  if (options.loss == "cauchy") return new ceres::CauchyLoss(options.loss_scale);
  return nullptr;  // "none"; SolverOptions::Check rejects other names.
}

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
  const FloorIntrinsics k{observation.fx, observation.fy, observation.cx, observation.cy,
                          observation.camera_height};
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  std::unique_ptr<ceres::LossFunction> loss(MakeLoss(options_));
  for (int side = -1; side <= 1; side += 2) {
    for (const auto& p : side < 0 ? observation.left : observation.right) {
      problem.AddResidualBlock(JunctionLineResidual::Create(k, p.x(), p.y(), side), loss.get(), x);
    }
  }
  problem.SetParameterLowerBound(x, 0, -lm.max_abs_yaw);
  problem.SetParameterUpperBound(x, 0, lm.max_abs_yaw);
  problem.SetParameterLowerBound(x, 1, -lm.max_abs_pitch);
  problem.SetParameterUpperBound(x, 1, lm.max_abs_pitch);
  problem.SetParameterLowerBound(x, 3, 0.05);
  ceres::Solver::Summary ceres_summary;
  ceres::Solve(LevenbergMarquardtOptions(lm), &problem, &ceres_summary);
  summary->evaluations = ceres_summary.num_residual_evaluations;
  summary->iterations = static_cast<int>(ceres_summary.iterations.size());
  summary->final_cost = ceres_summary.final_cost;
  summary->converged = ceres_summary.termination_type == ceres::CONVERGENCE;
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!ceres_summary.IsSolutionUsable()) {
    return Status::ImplausibleGeometry("joint solve failed: " + ceres_summary.message);
  }
  summary->estimate.yaw = x[0];
  summary->estimate.pitch = x[1];
  summary->estimate.offset = x[2];
  summary->estimate.width = x[3];
  summary->estimate.camera_height = observation.camera_height;
  return Status::Ok();
}

}  // namespace corridor
