#pragma once

// The joint solver's residual (beyond the paper): the perpendicular pixel distance of one edge
// point to the image of its 3D junction line (s_k w/2 - offset, h, Z), Z in R. Under Gaussian
// pixel noise, minimising these over (yaw, pitch, offset, width) at once is the maximum-
// likelihood estimate. The plane through the camera centre and the junction has the camera-frame
// normal N = h m - X n (m, n: wall and floor normals, X: the wall's X_W), and the image line is
// K^-T N, so the distance is (N . r) / |(N_x / fx, N_y / fy)| with r the point's normalised ray.

#include <ceres/autodiff_cost_function.h>

#include "corridor_depth/corridor_frame.h"
#include "corridor_depth/virtual_camera.h"

namespace corridor {

class JunctionLineResidual {
 public:
  static constexpr int kNumParameters = 4;  // yaw, pitch, offset, width

  // side: -1 for a left-junction point, +1 for a right one.
  JunctionLineResidual(const FloorIntrinsics& intrinsics, double u, double v, int side)
      : intrinsics_(intrinsics), u_(u), v_(v), side_(side) {}

  template <typename T>
  bool operator()(const T* x, T* residual) const {
    Vec3<T> line;
    if (!ScaledLine(intrinsics_, x, side_, &line)) return false;
    *residual = Distance(intrinsics_, line, u_, v_);
    return true;
  }

  // The side's junction at x as the plane normal N scaled by 1 / |(N_x / fx, N_y / fy)|, so that
  // Distance is in pixels. It depends on x alone: a solver over many points computes it once per
  // x (JointSolver). False when the line is at infinity.
  template <typename T>
  static bool ScaledLine(const FloorIntrinsics& intrinsics, const T* x, int side, Vec3<T>* line) {
    const CorridorRotation<T> rotation(x[1], x[0]);
    const Vec3<T> m = rotation.WallNormal(), n = rotation.FloorNormal();
    const T wall_x = T(0.5 * side) * x[3] - x[2];
    const T h(intrinsics.height);
    const Vec3<T> normal{h * m.x - wall_x * n.x, h * m.y - wall_x * n.y, h * m.z - wall_x * n.z};
    const T a = normal.x / T(intrinsics.fx), b = normal.y / T(intrinsics.fy);
    const T norm_sq = a * a + b * b;
    if (!(norm_sq > T(1e-30))) return false;
    using std::sqrt;
    const T scale = T(1.0) / sqrt(norm_sq);
    *line = Vec3<T>{normal.x * scale, normal.y * scale, normal.z * scale};
    return true;
  }

  // The signed pixel distance of (u, v) from a ScaledLine.
  template <typename T>
  static T Distance(const FloorIntrinsics& intrinsics, const Vec3<T>& line, double u, double v) {
    return line.x * ((u - intrinsics.cx) / intrinsics.fx) +
           line.y * ((v - intrinsics.cy) / intrinsics.fy) + line.z;
  }

  static ceres::CostFunction* Create(const FloorIntrinsics& intrinsics, double u, double v,
                                     int side) {
    return new ceres::AutoDiffCostFunction<JunctionLineResidual, 1, kNumParameters>(
        new JunctionLineResidual(intrinsics, u, v, side));
  }

 private:
  const FloorIntrinsics intrinsics_;
  const double u_, v_;
  const int side_;
};

}  // namespace corridor
