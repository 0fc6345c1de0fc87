// The robust loss scaled to the points' own spread (SolverOptions::loss_sigmas) and the trimming of
// "lm": edge points are placed to a tenth of a pixel, and a second edge a pixel from the junction
// (a baseboard's top, a shadow) pulls a fit whose loss treats every point within a fixed 2 px as
// an inlier; the fit scaled to the spread, and "lm" with trimming, stay on the junction. Truth:
// the hand-set geometry, its points projected with Eigen's rotations
// (tests/support/exact_observation.h), not with the solvers'; the spreads are hand-computed.

#include <vector>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "corridor_depth/solver.h"
#include "estimation/junction_trim.h"
#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using testing::ExactObservation;

const std::vector<CorridorGeometry> kTruths = testing::ExampleCorridors(1.2);

// The unit normal of the image line through a side's exact points (from its end points).
Eigen::Vector2d Normal(const std::vector<Eigen::Vector2d>& points) {
  const Eigen::Vector2d d = (points.back() - points.front()).normalized();
  return Eigen::Vector2d(-d.y(), d.x());
}

// Each side's points moved across their line by the given distances, px, with the given weights.
CorridorObservation Displaced(const CorridorGeometry& truth, const std::vector<double>& left,
                              const std::vector<double>& left_weights,
                              const std::vector<double>& right,
                              const std::vector<double>& right_weights) {
  CorridorObservation obs = ExactObservation(truth, 8);
  const Eigen::Vector2d nl = Normal(obs.left), nr = Normal(obs.right);
  obs.left.resize(left.size());
  obs.right.resize(right.size());
  for (size_t i = 0; i < left.size(); ++i) obs.left[i] += left[i] * nl;
  for (size_t i = 0; i < right.size(); ++i) obs.right[i] += right[i] * nr;
  obs.left_weights = left_weights;
  obs.right_weights = right_weights;
  return obs;
}

TEST(ResidualScaledLossTest, RobustSigmaIsTheScaledMedianOfTheWeightedDistances) {
  for (const auto& truth : kTruths) {
    // Weighted distances sqrt(w) |d|: left 0.2, 0.2, 0.3; right 0.2, 0.5.
    const CorridorObservation obs =
        Displaced(truth, {0.1, -0.2, 0.3}, {4, 1, 1}, {0.4, -0.5}, {0.25, 1});
    const FloorIntrinsics k{obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height};
    const double x[4] = {truth.yaw, truth.pitch, truth.offset, truth.width};
    double both = 0, left = 0, right = 0;
    ASSERT_TRUE(RobustSigma(obs, k, x, 0, &both));
    ASSERT_TRUE(RobustSigma(obs, k, x, -1, &left));
    ASSERT_TRUE(RobustSigma(obs, k, x, 1, &right));
    EXPECT_NEAR(both, 1.4826 * 0.2, 1e-6);   // median of 0.2, 0.2, 0.2, 0.3, 0.5
    EXPECT_NEAR(left, 1.4826 * 0.2, 1e-6);   // of 0.2, 0.2, 0.3
    EXPECT_NEAR(right, 1.4826 * 0.5, 1e-6);  // the upper median of 0.2, 0.5
  }
}

TEST(ResidualScaledLossTest, TrimmingKeepsThePointsWithinItsSigmas) {
  const CorridorGeometry& truth = kTruths[1];
  // Left weighted distances 0.1, 0.1, 0.1, 0.1, 0.9: sigma 0.14826, 3 sigma 0.445; right all 0.1.
  const CorridorObservation obs = Displaced(truth, {0.1, -0.1, 0.1, -0.1, 0.9}, {1, 1, 1, 1, 1},
                                            {0.1, -0.1, 0.1}, {1, 1, 1});
  const FloorIntrinsics k{obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height};
  const double x[4] = {truth.yaw, truth.pitch, truth.offset, truth.width};
  CorridorObservation kept;
  std::vector<char> mask;
  ASSERT_TRUE(TrimToFit(obs, k, x, 3.0, &kept, &mask));
  EXPECT_EQ(mask, (std::vector<char>{1, 1, 1, 1, 0, 1, 1, 1}));
  EXPECT_EQ(kept.left.size(), 4u);
  EXPECT_EQ(kept.right.size(), 3u);
  EXPECT_EQ(kept.fx, obs.fx);
  EXPECT_EQ(kept.camera_height, obs.camera_height);
}

// The truth's points with Gaussian noise of sigma px across their lines, and about one in four of
// each side's farther half on a second edge 0.5-1.5 px beside the junction, on the side `outward`
// (+1, the wall's, or -1, the floor's) names, measured strong (weight 3 where the others have 1),
// as a baseboard's top or a shadow's edge along the far junction.
CorridorObservation EdgeWithSecondEdge(const CorridorGeometry& truth, double sigma, int outward,
                                       unsigned seed) {
  CorridorObservation obs = ExactObservation(truth, 120, 2.0, 12.0);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::uniform_real_distribution<double> apart(0.5, 1.5);
  std::bernoulli_distribution second(0.25);
  for (int side = -1; side <= 1; side += 2) {
    std::vector<Eigen::Vector2d>& points = side < 0 ? obs.left : obs.right;
    std::vector<double>& weights = side < 0 ? obs.left_weights : obs.right_weights;
    // The normal pointing away from the image's centre column at the near end: toward the wall.
    Eigen::Vector2d normal = Normal(points);
    if (normal.x() * side < 0) normal = -normal;
    weights.assign(points.size(), 1.0);
    for (size_t i = 0; i < points.size(); ++i) {
      double d = noise(rng);
      if (i >= points.size() / 2 && second(rng)) {
        d += outward * apart(rng);
        weights[i] = 3.0;
      }
      points[i] += d * normal;
    }
  }
  return obs;
}

double WidthError(const std::string& solver_name, const SolverOptions& options,
                  const CorridorObservation& obs, const CorridorGeometry& truth) {
  std::unique_ptr<CorridorSolver> solver;
  EXPECT_TRUE(CreateSolver(solver_name, options, &solver).ok());
  SolverSummary summary;
  const Status status = solver->Solve(obs, nullptr, &summary);
  EXPECT_TRUE(status.ok()) << status.ToString();
  return std::abs(summary.estimate.width - truth.width) / truth.width;
}

TEST(ResidualScaledLossTest, ASecondEdgeWithinAPixelNoLongerPullsJointOrLm) {
  SolverOptions fixed;  // Huber of 2 px, as before the scale followed the points
  fixed.loss_sigmas = 0;
  const SolverOptions scaled;  // the defaults
  ASSERT_GT(scaled.loss_sigmas, 0);
  for (const char* solver : {"joint", "lm"}) {
    double fixed_sum = 0, scaled_sum = 0;
    unsigned seed = 1;
    for (const auto& truth : kTruths) {
      for (int outward : {-1, 1}) {
        for (int trial = 0; trial < 4; ++trial) {
          const CorridorObservation obs = EdgeWithSecondEdge(truth, 0.1, outward, seed++);
          const double fixed_error = WidthError(solver, fixed, obs, truth);
          const double scaled_error = WidthError(solver, scaled, obs, truth);
          fixed_sum += fixed_error;
          scaled_sum += scaled_error;
          EXPECT_LT(scaled_error, 0.002) << solver << " seed " << seed;
        }
      }
    }
    EXPECT_LT(scaled_sum, 0.5 * fixed_sum) << solver;
  }
}

TEST(ResidualScaledLossTest, PointsOnTheLinesGiveTheSameFitAsTheFixedScale) {
  // Points without spread: the scale falls to its guard, under which every residual is still in
  // the loss's quadratic part, and nothing is trimmed.
  SolverOptions fixed;
  fixed.loss_sigmas = 0;
  const SolverOptions scaled;
  for (const auto& truth : kTruths) {
    const CorridorObservation exact = ExactObservation(truth, 30);
    for (const char* name : {"joint", "lm"}) {
      std::unique_ptr<CorridorSolver> a_solver, b_solver;
      ASSERT_TRUE(CreateSolver(name, fixed, &a_solver).ok());
      ASSERT_TRUE(CreateSolver(name, scaled, &b_solver).ok());
      SolverSummary a, b;
      ASSERT_TRUE(a_solver->Solve(exact, nullptr, &a).ok());
      ASSERT_TRUE(b_solver->Solve(exact, nullptr, &b).ok());
      EXPECT_EQ(a.estimate.width, b.estimate.width) << name;
      EXPECT_EQ(a.estimate.yaw, b.estimate.yaw) << name;
      EXPECT_EQ(a.estimate.pitch, b.estimate.pitch) << name;
      EXPECT_EQ(a.estimate.offset, b.estimate.offset) << name;
      EXPECT_NEAR(b.estimate.width, truth.width, 1e-6 * truth.width) << name;
    }
  }
}

TEST(ResidualScaledLossTest, NegativeOrNonFiniteLossSigmasIsRejected) {
  SolverOptions options;
  std::string why;
  options.loss_sigmas = -1;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("loss_sigmas"), std::string::npos);
  options.loss_sigmas = std::nan("");
  EXPECT_FALSE(options.Check(&why));
  options.loss_sigmas = 0;
  EXPECT_TRUE(options.Check(&why)) << why;
}

}  // namespace
}  // namespace corridor
