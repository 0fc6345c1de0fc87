#pragma once

// The per-point half of the joint solver's linearisation (JunctionResiduals::Linearize): one
// junction's residuals, their robust cost, and the moments of their points from which its rows of
// J'J and J'f follow.

#include <vector>

#include <Eigen/Core>

#include "corridor_depth/virtual_camera.h"
#include "estimation/robust_loss.h"

namespace corridor {

// Moments of a side's points p = ((u - cx) / fx, (v - cy) / fy, 1): a = sum q^2 p p' and
// b = sum q f p, with f a point's residual after the loss's correction and q the factor of
// p' dl/dx in its corrected Jacobian row (the loss's Jacobian scale times sqrt(weight)).
struct SideMoments {
  double a[3][3] = {};
  double b[3] = {};
};

// For the points (their weights, or every weight 1 when `weights` is empty) of the side whose
// ScaledLine at x is `line` (its values): adds 1/2 rho(r^2) of each residual r to *cost in the
// points' order, as a sum over the residuals one by one gives it, and writes the moments, summed
// in four lanes (point i in lane i % 4; AVX2 where the CPU has it, the same operations without
// FMA). False when a residual is not finite.
bool AccumulateSideMoments(const FloorIntrinsics& intrinsics, const RobustLoss& loss,
                           const double line[3], const std::vector<Eigen::Vector2d>& points,
                           const std::vector<double>& weights, double* cost,
                           SideMoments* moments);

}  // namespace corridor
