#include <cmath>
#include <vector>

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include "estimation/junction_line_residual.h"
#include "corridor_depth/symmetry_residual.h"
#include "corridor_depth/width_residual.h"
#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using testing::ExactObservation;
using testing::MakeGeometry;
using testing::TrueRotation;

FloorIntrinsics Intrinsics(const CorridorObservation& obs) {
  return {obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height};
}

struct Pose {
  double yaw, pitch, offset, width, height;
};

class ResidualsAtTruth : public ::testing::TestWithParam<Pose> {};

TEST_P(ResidualsAtTruth, SymmetryResidualVanishesAtTruth) {
  const Pose p = GetParam();
  const auto obs = ExactObservation(MakeGeometry(p.yaw, p.pitch, p.offset, p.width, p.height));
  const SymmetryResidual functor(Intrinsics(obs), p.pitch, obs.left, obs.right);
  std::vector<double> r(functor.NumResiduals());
  const double x[2] = {p.yaw, p.offset};
  ASSERT_TRUE(functor(x, r.data()));
  for (double v : r) EXPECT_NEAR(v, 0.0, 1e-8);
}

TEST_P(ResidualsAtTruth, WidthResidualVanishesAtTruth) {
  const Pose p = GetParam();
  const auto obs = ExactObservation(MakeGeometry(p.yaw, p.pitch, p.offset, p.width, p.height));
  const WidthResidual functor(Intrinsics(obs), p.yaw, p.offset, obs.left, obs.right);
  std::vector<double> r(functor.NumResiduals());
  const double x[2] = {p.pitch, p.width};
  ASSERT_TRUE(functor(x, r.data()));
  for (double v : r) EXPECT_NEAR(v, 0.0, 1e-8);
}

// Width off by delta: by hand, r_k = -s_k fx delta / (2 z_k), z_k the point's true camera depth.
TEST_P(ResidualsAtTruth, WidthResidualOfWrongWidthMatchesHandFormula) {
  const Pose p = GetParam();
  const double delta = 0.1;
  const int n = 5;
  const auto obs =
      ExactObservation(MakeGeometry(p.yaw, p.pitch, p.offset, p.width, p.height), n, 2.0, 10.0);
  const WidthResidual functor(Intrinsics(obs), p.yaw, p.offset, obs.left, obs.right);
  std::vector<double> r(functor.NumResiduals());
  const double x[2] = {p.pitch, p.width + delta};
  ASSERT_TRUE(functor(x, r.data()));
  const Eigen::Matrix3d rot = TrueRotation(p.pitch, p.yaw);
  const double d_left = p.width / 2 + p.offset, d_right = p.width / 2 - p.offset;
  for (int i = 0; i < n; ++i) {
    const double zw = 2.0 + 8.0 * i / (n - 1);
    const double z_left = (rot * Eigen::Vector3d(-d_left, p.height, zw)).z();
    const double z_right = (rot * Eigen::Vector3d(d_right, p.height, zw)).z();
    EXPECT_NEAR(r[i], +obs.fx * delta / (2 * z_left), 1e-8);
    EXPECT_NEAR(r[n + i], -obs.fx * delta / (2 * z_right), 1e-8);
  }
}

// Offset off by delta at the true yaw: every virtual point moves by fx delta / Z_V, so the
// mirrored left point and the right line part by 2 fx delta / Z_V, with Z_V the virtual depth
// h sin(theta) + Z_W cos(theta) of the floor point (hand-derived).
TEST_P(ResidualsAtTruth, SymmetryResidualOfWrongOffsetMatchesHandFormula) {
  const Pose p = GetParam();
  const double delta = 0.05;
  const int n = 5;
  const auto obs =
      ExactObservation(MakeGeometry(p.yaw, p.pitch, p.offset, p.width, p.height), n, 2.0, 10.0);
  const SymmetryResidual functor(Intrinsics(obs), p.pitch, obs.left, obs.right);
  std::vector<double> r(functor.NumResiduals());
  const double x[2] = {p.yaw, p.offset + delta};
  ASSERT_TRUE(functor(x, r.data()));
  for (int i = 0; i < n; ++i) {
    const double zw = 2.0 + 8.0 * i / (n - 1);
    const double z_virtual = p.height * std::sin(p.pitch) + zw * std::cos(p.pitch);
    EXPECT_NEAR(r[i], -2 * obs.fx * delta / z_virtual, 1e-7);
    EXPECT_NEAR(r[n + i], -2 * obs.fx * delta / z_virtual, 1e-7);
  }
}

// Autodiff Jacobians against central numeric differences of the same functor.
template <typename Functor>
void ExpectJacobianMatchesNumeric(const Functor& functor, const double x[2]) {
  const int m = functor.NumResiduals();
  ceres::AutoDiffCostFunction<Functor, ceres::DYNAMIC, 2> autodiff(new Functor(functor), m);
  ceres::NumericDiffCostFunction<Functor, ceres::CENTRAL, ceres::DYNAMIC, 2> numeric(
      new Functor(functor), ceres::TAKE_OWNERSHIP, m);
  std::vector<double> r1(m), r2(m), j1(2 * m), j2(2 * m);
  const double* params[1] = {x};
  double* jac1[1] = {j1.data()};
  double* jac2[1] = {j2.data()};
  ASSERT_TRUE(autodiff.Evaluate(params, r1.data(), jac1));
  ASSERT_TRUE(numeric.Evaluate(params, r2.data(), jac2));
  for (int i = 0; i < 2 * m; ++i) {
    EXPECT_NEAR(j1[i], j2[i], 1e-5 * std::max(1.0, std::abs(j2[i]))) << "entry " << i;
  }
}

TEST_P(ResidualsAtTruth, JacobiansMatchNumericDifferentiation) {
  const Pose p = GetParam();
  const auto obs = ExactObservation(MakeGeometry(p.yaw, p.pitch, p.offset, p.width, p.height));
  const SymmetryResidual symmetry(Intrinsics(obs), p.pitch + 0.01, obs.left, obs.right);
  const double x1[2] = {p.yaw + 0.03, p.offset - 0.1};
  ExpectJacobianMatchesNumeric(symmetry, x1);
  const WidthResidual width(Intrinsics(obs), p.yaw - 0.02, p.offset + 0.05, obs.left, obs.right);
  const double x2[2] = {p.pitch - 0.02, p.width * 1.1};
  ExpectJacobianMatchesNumeric(width, x2);
}

INSTANTIATE_TEST_SUITE_P(Poses, ResidualsAtTruth,
                         ::testing::Values(Pose{0.0, 0.0, 0.0, 2.0, 0.66},
                                           Pose{0.1, 0.05, 0.2, 2.4, 0.62},
                                           Pose{-0.2, 0.12, -0.3, 3.1, 0.66},
                                           Pose{0.25, -0.05, 0.4, 1.8, 1.0}));

TEST(ResidualsTest, RejectPointsAboveTheHorizon) {
  CorridorObservation obs = ExactObservation(MakeGeometry(0, 0, 0, 2, 0.66));
  obs.left[0].y() = obs.cy - 50;  // Above the horizon of a level camera: not a floor point.
  const WidthResidual functor({obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height}, 0, 0,
                              obs.left, obs.right);
  std::vector<double> r(functor.NumResiduals());
  const double x[2] = {0.0, 2.0};
  EXPECT_FALSE(functor(x, r.data()));
}

}  // namespace
}  // namespace corridor

namespace corridor {
namespace {

// The joint residual is the perpendicular pixel distance to the true junction's image, which
// the test builds from two projected 3D points with Eigen.
TEST(JunctionLineResidualTest, MatchesPerpendicularDistanceToProjectedLine) {
  const auto g = testing::MakeGeometry(0.12, 0.07, -0.2, 2.5, 0.66);
  const CorridorObservation obs = testing::ExactObservation(g);
  const FloorIntrinsics k{obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height};
  const Eigen::Matrix3d r = testing::TrueRotation(g.pitch, g.yaw);
  const double params[4] = {g.yaw, g.pitch, g.offset, g.width};
  for (int side = -1; side <= 1; side += 2) {
    const double x = side < 0 ? -(g.width / 2 + g.offset) : g.width / 2 - g.offset;
    const auto project = [&](double z) {
      const Eigen::Vector3d c = r * Eigen::Vector3d(x, g.camera_height, z);
      return Eigen::Vector2d(obs.fx * c.x() / c.z() + obs.cx, obs.fy * c.y() / c.z() + obs.cy);
    };
    const Eigen::Vector2d a = project(3.0), b = project(9.0);
    const Eigen::Vector2d normal = Eigen::Vector2d(-(b - a).y(), (b - a).x()).normalized();
    for (double offset_px : {0.0, 2.5, -7.0}) {
      const Eigen::Vector2d p = a + 0.3 * (b - a) + offset_px * normal;
      const JunctionLineResidual residual(k, p.x(), p.y(), side);
      double value;
      ASSERT_TRUE(residual(params, &value));
      EXPECT_NEAR(std::abs(value), std::abs(offset_px), 1e-7);
    }
  }
}

TEST(JunctionLineResidualTest, JacobianMatchesNumericDifferentiation) {
  const auto g = testing::MakeGeometry(-0.1, 0.04, 0.3, 2.2, 0.62);
  const CorridorObservation obs = testing::ExactObservation(g);
  const FloorIntrinsics k{obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height};
  const double x[4] = {g.yaw + 0.02, g.pitch - 0.01, g.offset + 0.05, g.width - 0.1};
  const JunctionLineResidual functor(k, obs.left[5].x() + 1.0, obs.left[5].y(), -1);
  ceres::AutoDiffCostFunction<JunctionLineResidual, 1, 4> autodiff(new JunctionLineResidual(functor));
  ceres::NumericDiffCostFunction<JunctionLineResidual, ceres::CENTRAL, 1, 4> numeric(
      new JunctionLineResidual(functor));
  double r1, r2, j1[4], j2[4];
  const double* params[1] = {x};
  double* jac1[1] = {j1};
  double* jac2[1] = {j2};
  ASSERT_TRUE(autodiff.Evaluate(params, &r1, jac1));
  ASSERT_TRUE(numeric.Evaluate(params, &r2, jac2));
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(j1[i], j2[i], 1e-5 * std::max(1.0, std::abs(j2[i])));
}

}  // namespace
}  // namespace corridor
