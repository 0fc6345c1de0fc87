#pragma once

// Stage 2 of the paper (III-C.2, eq. 16), made exact in docs/geometry.md section 5.
// Parameters: x = (pitch, width). Yaw and offset are held fixed.
// Each junction point, back-projected to the floor, must lie on its wall:
//   r_k = X_W,k - (s_k w/2 - offset),  s = -1 left, +1 right,
// weighted by fx / z_k so that it reads in pixels. With X_W = z (m.r) and z = h / (n.r) this is
//   r_k = fx [ (m.r) - (s_k w/2 - offset) (n.r) / h ],
// which has no division and stays smooth as points approach the horizon. With point weights
// (CorridorObservation), each residual is scaled by the square root of its point's weight before
// the loss.

#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <ceres/autodiff_cost_function.h>

#include "corridor_depth/residual_loss.h"
#include "corridor_depth/virtual_camera.h"

namespace corridor {

class WidthResidual {
 public:
  static constexpr int kNumParameters = 2;  // pitch, width

  WidthResidual(const FloorIntrinsics& intrinsics, double yaw, double offset,
                std::vector<Eigen::Vector2d> left, std::vector<Eigen::Vector2d> right,
                ResidualLoss loss = ResidualLoss(), const std::vector<double>& left_weights = {},
                const std::vector<double>& right_weights = {})
      : intrinsics_(intrinsics),
        loss_(loss),
        yaw_(yaw),
        offset_(offset),
        left_(std::move(left)),
        right_(std::move(right)),
        left_scale_(SquareRoots(left_weights)),
        right_scale_(SquareRoots(right_weights)) {}

  int NumResiduals() const { return static_cast<int>(left_.size() + right_.size()); }

  template <typename T>
  bool operator()(const T* x, T* residuals) const {
    const CorridorRotation<T> rotation(x[0], T(yaw_));
    const T half_width = T(0.5) * x[1];
    int k = 0;
    for (size_t i = 0; i < left_.size(); ++i) {
      const double scale = left_scale_.empty() ? 1.0 : left_scale_[i];
      if (!PointResidual(rotation, left_[i], -half_width - T(offset_), scale, &residuals[k++])) {
        return false;
      }
    }
    for (size_t i = 0; i < right_.size(); ++i) {
      const double scale = right_scale_.empty() ? 1.0 : right_scale_[i];
      if (!PointResidual(rotation, right_[i], half_width - T(offset_), scale, &residuals[k++])) {
        return false;
      }
    }
    return true;
  }

  static ceres::CostFunction* Create(const FloorIntrinsics& intrinsics, double yaw, double offset,
                                     std::vector<Eigen::Vector2d> left,
                                     std::vector<Eigen::Vector2d> right,
                                     ResidualLoss loss = ResidualLoss()) {
    auto* functor =
        new WidthResidual(intrinsics, yaw, offset, std::move(left), std::move(right), loss);
    return new ceres::AutoDiffCostFunction<WidthResidual, ceres::DYNAMIC, kNumParameters>(
        functor, functor->NumResiduals());
  }

 private:
  static std::vector<double> SquareRoots(const std::vector<double>& weights) {
    std::vector<double> roots(weights.size());
    for (size_t i = 0; i < weights.size(); ++i) roots[i] = std::sqrt(weights[i]);
    return roots;
  }

  // wall_x: the wall's X_W (-d_l or +d_r); scale: the square root of the point's weight.
  template <typename T>
  bool PointResidual(const CorridorRotation<T>& rotation, const Eigen::Vector2d& p,
                     const T& wall_x, double scale, T* residual) const {
    const Vec3<T> ray{T((p.x() - intrinsics_.cx) / intrinsics_.fx),
                      T((p.y() - intrinsics_.cy) / intrinsics_.fy), T(1.0)};
    const T n_dot_r = Dot(rotation.FloorNormal(), ray);
    if (!(n_dot_r > T(1e-9))) return false;  // Not a floor point in front of the camera.
    const T m_dot_r = Dot(rotation.WallNormal(), ray);
    *residual = loss_.Apply(T(scale * intrinsics_.fx) *
                            (m_dot_r - wall_x * n_dot_r / T(intrinsics_.height)));
    return true;
  }

  const FloorIntrinsics intrinsics_;
  const ResidualLoss loss_;
  const double yaw_;
  const double offset_;
  const std::vector<Eigen::Vector2d> left_;
  const std::vector<Eigen::Vector2d> right_;
  const std::vector<double> left_scale_, right_scale_;  // Square roots of the weights; empty: 1.
};

}  // namespace corridor
