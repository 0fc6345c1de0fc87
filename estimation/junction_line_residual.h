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
    const CorridorRotation<T> rotation(x[1], x[0]);
    const Vec3<T> m = rotation.WallNormal(), n = rotation.FloorNormal();
    const T wall_x = T(0.5 * side_) * x[3] - x[2];
    const T h(intrinsics_.height);
    const Vec3<T> normal{h * m.x - wall_x * n.x, h * m.y - wall_x * n.y, h * m.z - wall_x * n.z};
    const Vec3<T> ray{T((u_ - intrinsics_.cx) / intrinsics_.fx),
                      T((v_ - intrinsics_.cy) / intrinsics_.fy), T(1.0)};
    const T a = normal.x / T(intrinsics_.fx), b = normal.y / T(intrinsics_.fy);
    const T norm_sq = a * a + b * b;
    if (!(norm_sq > T(1e-30))) return false;
    using std::sqrt;
    residual[0] = Dot(normal, ray) / sqrt(norm_sq);
    return true;
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
