#pragma once

// The joint solver's residuals for SolveBoundedLm: the JunctionLineResidual of every edge point,
// times the square root of its weight (the maximum-likelihood fit for points of variance
// 1 / weight): the left junction's points, then the right's. Prepare computes the two sides'
// lines once per x; each residual is then a point's distance from its side's line.

#include <cmath>
#include <type_traits>
#include <vector>

#include <ceres/jet.h>

#include "corridor_depth/corridor_observation.h"
#include "estimation/bounded_lm.h"
#include "estimation/junction_line_residual.h"
#include "estimation/robust_loss.h"

namespace corridor {

class JunctionResiduals {
 public:
  using Jet = ceres::Jet<double, 4>;
  JunctionResiduals(const CorridorObservation& observation, const FloorIntrinsics& intrinsics)
      : observation_(observation), intrinsics_(intrinsics) {}

  int size() const {
    return static_cast<int>(observation_.left.size() + observation_.right.size());
  }

  bool Prepare(const double* x) const { return PrepareInto(x, lines_); }
  bool Prepare(const Jet* x) const { return PrepareInto(x, jet_lines_); }

  template <typename T>
  bool operator()(int i, const T* /*x, in the lines Prepare computed*/, T* residual) const {
    const int left = static_cast<int>(observation_.left.size());
    const int side = i < left ? -1 : 1;
    const size_t k = static_cast<size_t>(i < left ? i : i - left);
    const auto& p = side < 0 ? observation_.left[k] : observation_.right[k];
    *residual = JunctionLineResidual::Distance(intrinsics_, Lines<T>()[side < 0 ? 0 : 1], p.x(),
                                               p.y());
    const std::vector<double>& weights =
        side < 0 ? observation_.left_weights : observation_.right_weights;
    if (!weights.empty()) *residual *= std::sqrt(weights[k]);
    return true;
  }

  // What bounded_lm::LinearizeWithJets gives for these residuals, up to rounding, without a Jet
  // per point: a residual is affine in its point p = ((u - cx) / fx, (v - cy) / fy, 1), so its
  // derivative row is sqrt(w) p' dl/dx, and J'J and J'f follow from each side's moments of p
  // (weighted by the loss's factors) and the side line's 3x4 derivative dl/dx, taken once per
  // side with Jets. Only the residual itself, which the loss needs, is computed per point.
  bool Linearize(const RobustLoss& loss, const double* x,
                 bounded_lm::Linearization<4>* lin) const;

 private:
  template <typename T>
  bool PrepareInto(const T* x, Vec3<T>* out) const {
    return JunctionLineResidual::ScaledLine(intrinsics_, x, -1, &out[0]) &&
           JunctionLineResidual::ScaledLine(intrinsics_, x, 1, &out[1]);
  }
  template <typename T>
  const Vec3<T>* Lines() const {
    if constexpr (std::is_same_v<T, double>) {
      return lines_;
    } else {
      return jet_lines_;
    }
  }

  const CorridorObservation& observation_;
  const FloorIntrinsics intrinsics_;
  mutable Vec3<double> lines_[2] = {};  // Prepare's, at the x of the residuals that follow.
  mutable Vec3<Jet> jet_lines_[2] = {};
};

}  // namespace corridor
