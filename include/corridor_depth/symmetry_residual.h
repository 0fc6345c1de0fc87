#pragma once

// Stage 1 of the paper (III-B, eqs. 8-9), made exact in docs/geometry.md section 5.
// Parameters: x = (yaw, offset). Pitch and camera height are held fixed.
// Each left point is mapped to the virtual image and mirrored about u = cx; its residual is the
// horizontal pixel distance to the mapped right line at the same virtual row (and vice versa).
// The opposite line is fitted to that side's inliers only (see LineInlierMask), so that gross
// outliers from door frames or grout lines do not drag it; their own residuals remain for a
// robust loss to down-weight. With point weights (CorridorObservation), each residual is scaled by
// the square root of its point's weight before the loss, and the opposite lines are weighted fits.

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <ceres/autodiff_cost_function.h>

#include "corridor_depth/line_inliers.h"
#include "corridor_depth/residual_loss.h"
#include "corridor_depth/virtual_camera.h"

namespace corridor {

class SymmetryResidual {
 public:
  static constexpr int kNumParameters = 2;  // yaw, offset

  SymmetryResidual(const FloorIntrinsics& intrinsics, double pitch,
                   std::vector<Eigen::Vector2d> left, std::vector<Eigen::Vector2d> right,
                   ResidualLoss loss = ResidualLoss(), std::vector<double> left_weights = {},
                   std::vector<double> right_weights = {})
      : intrinsics_(intrinsics),
        loss_(loss),
        pitch_(pitch),
        left_(std::move(left)),
        right_(std::move(right)),
        left_inliers_(LineInlierMask(left_)),
        right_inliers_(LineInlierMask(right_)),
        left_weights_(std::move(left_weights)),
        right_weights_(std::move(right_weights)),
        left_scale_(SquareRoots(left_weights_)),
        right_scale_(SquareRoots(right_weights_)) {}

  int NumResiduals() const { return static_cast<int>(left_.size() + right_.size()); }

  template <typename T>
  bool operator()(const T* x, T* residuals) const {
    const T pitch(pitch_);
    const CorridorRotation<T> rotation(pitch, x[0]);
    std::vector<T> ul(left_.size()), vl(left_.size()), ur(right_.size()), vr(right_.size());
    if (!MapAll(rotation, pitch, x[1], left_, &ul, &vl)) return false;
    if (!MapAll(rotation, pitch, x[1], right_, &ur, &vr)) return false;
    T a_left, b_left, a_right, b_right;  // u = a v + b in the virtual image
    if (!FitColumnOfRow(ul, vl, left_inliers_, left_weights_, &a_left, &b_left)) return false;
    if (!FitColumnOfRow(ur, vr, right_inliers_, right_weights_, &a_right, &b_right)) {
      return false;
    }
    const T two_cx(2.0 * intrinsics_.cx);
    int k = 0;
    for (size_t i = 0; i < ul.size(); ++i) {
      const T r = (two_cx - ul[i]) - (a_right * vl[i] + b_right);
      residuals[k++] = loss_.Apply(left_scale_.empty() ? r : T(left_scale_[i]) * r);
    }
    for (size_t i = 0; i < ur.size(); ++i) {
      const T r = (two_cx - ur[i]) - (a_left * vr[i] + b_left);
      residuals[k++] = loss_.Apply(right_scale_.empty() ? r : T(right_scale_[i]) * r);
    }
    return true;
  }

  // A Ceres cost with as many residuals as points; the functor is owned by the cost.
  static ceres::CostFunction* Create(const FloorIntrinsics& intrinsics, double pitch,
                                     std::vector<Eigen::Vector2d> left,
                                     std::vector<Eigen::Vector2d> right,
                                     ResidualLoss loss = ResidualLoss()) {
    auto* functor =
        new SymmetryResidual(intrinsics, pitch, std::move(left), std::move(right), loss);
    return new ceres::AutoDiffCostFunction<SymmetryResidual, ceres::DYNAMIC, kNumParameters>(
        functor, functor->NumResiduals());
  }

 private:
  template <typename T>
  bool MapAll(const CorridorRotation<T>& rotation, const T& pitch, const T& offset,
              const std::vector<Eigen::Vector2d>& points, std::vector<T>* u,
              std::vector<T>* v) const {
    for (size_t i = 0; i < points.size(); ++i) {
      if (!MapToVirtualImage(intrinsics_, rotation, pitch, offset, points[i].x(), points[i].y(),
                             &(*u)[i], &(*v)[i])) {
        return false;
      }
    }
    return true;
  }

  static std::vector<double> SquareRoots(const std::vector<double>& weights) {
    std::vector<double> roots(weights.size());
    for (size_t i = 0; i < weights.size(); ++i) roots[i] = std::sqrt(weights[i]);
    return roots;
  }

  // Line u = a v + b through the mapped inliers (least squares, weighted when weights are given).
  template <typename T>
  static bool FitColumnOfRow(const std::vector<T>& u, const std::vector<T>& v,
                             const std::vector<char>& keep, const std::vector<double>& weights,
                             T* a, T* b) {
    return FitSubset(u, v, keep, weights, a, b);
  }

  template <typename T>
  static bool FitSubset(const std::vector<T>& u, const std::vector<T>& v,
                        const std::vector<char>& keep, const std::vector<double>& weights, T* a,
                        T* b) {
    T n(0.0), sv(0.0), su(0.0), svv(0.0), svu(0.0);
    for (size_t i = 0; i < u.size(); ++i) {
      if (!keep[i]) continue;
      const T w(weights.empty() ? 1.0 : weights[i]);
      n += w;
      sv += w * v[i];
      su += w * u[i];
      svv += w * v[i] * v[i];
      svu += w * v[i] * u[i];
    }
    const T det = n * svv - sv * sv;
    using std::abs;
    if (!(abs(det) > T(1e-12))) return false;
    *a = (n * svu - sv * su) / det;
    *b = (su - *a * sv) / n;
    return true;
  }

  const FloorIntrinsics intrinsics_;
  const ResidualLoss loss_;
  const double pitch_;
  const std::vector<Eigen::Vector2d> left_;
  const std::vector<Eigen::Vector2d> right_;
  // Which points fit each side's opposite line. The real-to-virtual mapping is a homography of
  // the floor, so a point off its junction line in the real image is off it in the virtual image
  // too: the mask is found once, in the real image, and does not depend on the parameters.
  const std::vector<char> left_inliers_;
  const std::vector<char> right_inliers_;
  const std::vector<double> left_weights_, right_weights_;  // Empty: every weight 1.
  const std::vector<double> left_scale_, right_scale_;      // Their square roots.
};

}  // namespace corridor
