#include "estimation/alternation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "estimation/junction_trim.h"

namespace corridor {
namespace {

// The smallest pitch at which every junction point lies below the horizon (n.r > 0), plus a
// margin: a pitch prior below it would make the points miss the floor in the first stage.
double LowestValidPitch(const CorridorObservation& observation) {
  double highest = std::numeric_limits<double>::infinity();  // Smallest (v - cy) / fy.
  for (const auto* side : {&observation.left, &observation.right}) {
    for (const auto& p : *side) highest = std::min(highest, (p.y() - observation.cy) / observation.fy);
  }
  constexpr double kMargin = 0.02;  // rad
  return std::atan(-highest) + kMargin;
}

// The robust standard deviation of a stage's residuals at x (each scaled by the square root of
// its point's weight, with no loss): 1.4826 times their median absolute value. False when the
// functor cannot be evaluated there.
template <typename Functor>
bool StageSigma(const Functor& plain, const double x[2], double* sigma) {
  thread_local std::vector<double> thread_residuals;
  std::vector<double>& residuals = thread_residuals;
  residuals.resize(plain.NumResiduals());
  if (residuals.empty() || !plain(x, residuals.data())) return false;
  for (double& r : residuals) {
    if (!std::isfinite(r)) return false;
    r = std::abs(r);
  }
  const size_t mid = residuals.size() / 2;
  std::nth_element(residuals.begin(), residuals.begin() + mid, residuals.end());
  *sigma = 1.4826 * residuals[mid];
  return true;
}

// The loss of a stage starting at x: of scale loss_sigmas robust standard deviations of the plain
// functor's residuals there, or the fixed `fixed` when loss_sigmas is 0 or they cannot be had.
template <typename Functor>
ResidualLoss StageLoss(const Functor& plain, const double x[2], double loss_sigmas,
                       const ResidualLoss& fixed) {
  double sigma = 0;
  if (!(loss_sigmas > 0) || !StageSigma(plain, x, &sigma)) return fixed;
  ResidualLoss loss = fixed;
  loss.scale = loss_sigmas * std::max(sigma, kMinSigmaPx);
  return loss;
}

}  // namespace

Status RunAlternation(const CorridorObservation& observation, const CorridorGeometry* initial,
                      const SolverOptions& options, const StageMinimizer& minimizer,
                      SolverSummary* summary, bool scale_loss_to_residuals) {
  std::string why;
  if (!observation.Check(&why)) return Status::InvalidArgument(why);
  const FloorIntrinsics k{observation.fx, observation.fy, observation.cx, observation.cy,
                          observation.camera_height};
  double yaw = initial ? initial->yaw : 0.0;
  double offset = initial ? initial->offset : 0.0;
  double pitch = initial ? initial->pitch
                         : std::max(options.initial_pitch, LowestValidPitch(observation));
  double width = initial && initial->width > 0 ? initial->width : options.lm.initial_width;

  ResidualLoss loss;
  if (!ResidualLoss::FromName(options.loss, options.loss_scale, &loss)) {
    return Status::InvalidArgument("unknown loss '" + options.loss + "'");
  }
  summary->converged = false;
  for (int round = 0; round < options.max_rounds; ++round) {
    const double before[4] = {yaw, offset, pitch, width};
    double x1[2] = {yaw, offset};
    const double loss_sigmas = scale_loss_to_residuals ? options.loss_sigmas : 0.0;
    const ResidualLoss symmetry_loss =
        loss_sigmas > 0 ? StageLoss(SymmetryResidual(k, pitch, observation.left, observation.right,
                                                     ResidualLoss(), observation.left_weights,
                                                     observation.right_weights),
                                    x1, loss_sigmas, loss)
                        : loss;
    const SymmetryResidual symmetry(k, pitch, observation.left, observation.right, symmetry_loss,
                                    observation.left_weights, observation.right_weights);
    if (!minimizer.MinimizeSymmetry(symmetry, x1, &summary->final_cost, &summary->evaluations)) {
      return Status::ImplausibleGeometry(
          "symmetry stage found no yaw/offset for which the junction points lie on the floor");
    }
    yaw = x1[0];
    offset = x1[1];
    double x2[2] = {pitch, width};
    const ResidualLoss width_loss =
        loss_sigmas > 0 ? StageLoss(WidthResidual(k, yaw, offset, observation.left,
                                                  observation.right, ResidualLoss(),
                                                  observation.left_weights,
                                                  observation.right_weights),
                                    x2, loss_sigmas, loss)
                        : loss;
    const WidthResidual distance(k, yaw, offset, observation.left, observation.right, width_loss,
                                 observation.left_weights, observation.right_weights);
    if (!minimizer.MinimizeWidth(distance, x2, &summary->final_cost, &summary->evaluations)) {
      return Status::ImplausibleGeometry(
          "width stage found no pitch/width for which the junction points lie on the floor");
    }
    pitch = x2[0];
    width = x2[1];
    summary->iterations = round + 1;
    const double after[4] = {yaw, offset, pitch, width};
    double change = 0;
    for (int i = 0; i < 4; ++i) change = std::max(change, std::abs(after[i] - before[i]));
    if (change < options.round_tolerance) {
      summary->converged = true;
      break;
    }
  }
  summary->estimate.yaw = yaw;
  summary->estimate.offset = offset;
  summary->estimate.pitch = pitch;
  summary->estimate.width = width;
  summary->estimate.camera_height = observation.camera_height;
  return Status::Ok();
}

}  // namespace corridor
