#include "estimation/alternation.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

}  // namespace

Status RunAlternation(const CorridorObservation& observation, const CorridorGeometry* initial,
                      const SolverOptions& options, const StageMinimizer& minimizer,
                      SolverSummary* summary) {
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
    const SymmetryResidual symmetry(k, pitch, observation.left, observation.right, loss,
                                    observation.left_weights, observation.right_weights);
    if (!minimizer.MinimizeSymmetry(symmetry, x1, &summary->final_cost, &summary->evaluations)) {
      return Status::ImplausibleGeometry(
          "symmetry stage found no yaw/offset for which the junction points lie on the floor");
    }
    yaw = x1[0];
    offset = x1[1];
    double x2[2] = {pitch, width};
    const WidthResidual distance(k, yaw, offset, observation.left, observation.right, loss,
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
