// JunctionResiduals::Linearize, the joint solver's normal equations from per-side moments,
// against bounded_lm::LinearizeWithJets (a Jet per point) and against central differences of the
// cost: noisy points of the example corridors, random weights, every loss, and x away from the
// truth so that some points fall in the losses' robust range. The moments are summed in four
// lanes (AVX2 for no loss and Huber's where the CPU has it): every remainder of points is tried.

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "estimation/bounded_lm.h"
#include "estimation/junction_residuals.h"
#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using Linearization = bounded_lm::Linearization<4>;

// R'R and R'z, which R'R = J'J and R'z = J'f define (upper triangle and column 4).
void NormalOf(const Linearization& lin, double normal[4][5]) {
  for (int k = 0; k < 4; ++k) {
    for (int j = k; j <= 4; ++j) {
      normal[k][j] = 0;
      for (int m = 0; m <= std::min(k, j); ++m) normal[k][j] += lin.r[m][k] * lin.r[m][j];
    }
  }
}

// `count` points a side of an example corridor moved by Gaussian noise of `noise_px`, with
// outliers and random weights (none on one side when `left_unweighted`).
CorridorObservation NoisyObservation(const CorridorGeometry& truth, int count, double noise_px,
                                     bool left_unweighted, std::mt19937* rng) {
  CorridorObservation obs = testing::ExactObservation(truth, count);
  std::normal_distribution<double> noise(0.0, noise_px);
  std::uniform_real_distribution<double> weight(0.2, 3.0), unit(0.0, 1.0);
  for (auto* side : {&obs.left, &obs.right}) {
    for (auto& p : *side) {
      p += Eigen::Vector2d(noise(*rng), noise(*rng));
      if (unit(*rng) < 0.1) p.y() += 6.0 * noise_px;  // an outlier
    }
  }
  if (!left_unweighted) {
    for (size_t i = 0; i < obs.left.size(); ++i) obs.left_weights.push_back(weight(*rng));
  }
  for (size_t i = 0; i < obs.right.size(); ++i) obs.right_weights.push_back(weight(*rng));
  return obs;
}

class JunctionResidualsLinearize : public ::testing::TestWithParam<std::string> {};

TEST_P(JunctionResidualsLinearize, MatchesTheJetPathAndNumericGradient) {
  std::mt19937 rng(7);
  std::normal_distribution<double> perturb(0.0, 1.0);
  int cases = 0;
  for (const CorridorGeometry& truth : testing::ExampleCorridors(1.2)) {
    for (int trial = 0; trial < 4; ++trial) {
      // 37 to 40 points: the four-lane sums with each remainder.
      const CorridorObservation obs =
          NoisyObservation(truth, 37 + trial, 0.5 + trial, trial == 1, &rng);
      const FloorIntrinsics intrinsics{obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height};
      const JunctionResiduals residuals(obs, intrinsics);
      const RobustLoss loss = RobustLoss::FromName(GetParam(), 0.5 + 0.5 * trial);
      const double x[4] = {truth.yaw + 0.02 * perturb(rng), truth.pitch + 0.02 * perturb(rng),
                           truth.offset + 0.05 * perturb(rng), truth.width + 0.1 * perturb(rng)};
      Linearization moments, jets;
      bounded_lm::Linearize<4>(residuals, loss, x, &moments);
      bounded_lm::LinearizeWithJets<4>(residuals, loss, x, &jets);
      ASSERT_TRUE(moments.ok);
      ASSERT_TRUE(jets.ok);
      ++cases;
      for (int k = 0; k < 4; ++k) EXPECT_EQ(moments.x[k], x[k]);
      EXPECT_NEAR(moments.cost, jets.cost, 1e-12 * jets.cost);
      double a[4][5], b[4][5], scale = 0;
      NormalOf(moments, a);
      NormalOf(jets, b);
      for (int k = 0; k < 4; ++k) {
        for (int j = k; j <= 4; ++j) scale = std::max(scale, std::abs(b[k][j]));
      }
      for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(moments.gradient[k], jets.gradient[k], 1e-9 * scale) << k;
        EXPECT_NEAR(moments.column_sq[k], jets.column_sq[k], 1e-9 * jets.column_sq[k]) << k;
        for (int j = k; j <= 4; ++j) EXPECT_NEAR(a[k][j], b[k][j], 1e-9 * scale) << k << j;
      }
      // The gradient of the cost is J'f: every loss here has rho'' <= 0, where the corrected
      // residual and Jacobian are both scaled by sqrt(rho').
      for (int k = 0; k < 4; ++k) {
        const double h = 1e-6 * std::max(1.0, std::abs(x[k]));
        double plus[4] = {x[0], x[1], x[2], x[3]}, minus[4] = {x[0], x[1], x[2], x[3]};
        plus[k] += h;
        minus[k] -= h;
        double cost_plus = 0, cost_minus = 0;
        ASSERT_TRUE(bounded_lm::EvaluateCost<4>(residuals, loss, plus, &cost_plus));
        ASSERT_TRUE(bounded_lm::EvaluateCost<4>(residuals, loss, minus, &cost_minus));
        const double numeric = (cost_plus - cost_minus) / (2 * h);
        EXPECT_NEAR(moments.gradient[k], numeric, 1e-5 * std::max(1.0, std::abs(numeric))) << k;
      }
    }
  }
  EXPECT_EQ(cases, 16);
}

INSTANTIATE_TEST_SUITE_P(Losses, JunctionResidualsLinearize,
                         ::testing::Values("none", "huber", "cauchy"));

TEST(JunctionResidualsLinearizeFailure, LineAtInfinityFailsAsTheJetPathDoes) {
  const CorridorGeometry truth = testing::ExampleCorridors()[0];
  const CorridorObservation obs = testing::ExactObservation(truth, 5);
  // camera height 0 and the camera on the wall: the plane's normal vanishes.
  const FloorIntrinsics intrinsics{obs.fx, obs.fy, obs.cx, obs.cy, 0.0};
  const JunctionResiduals residuals(obs, intrinsics);
  const double x[4] = {0, 0, -1.0, 2.0};  // the left wall at X = 0
  Linearization moments, jets;
  bounded_lm::Linearize<4>(residuals, RobustLoss(), x, &moments);
  bounded_lm::LinearizeWithJets<4>(residuals, RobustLoss(), x, &jets);
  EXPECT_FALSE(moments.ok);
  EXPECT_FALSE(jets.ok);
}

}  // namespace
}  // namespace corridor
