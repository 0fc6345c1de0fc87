// The joint solver's own Levenberg-Marquardt against a Ceres solve of the same problem (one
// AutoDiffCostFunction of JunctionLineResidual per edge point, the same loss and bounds, Ceres's
// LM with the project's settings), which is the reference path.

#include <vector>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include "estimation/ceres_options.h"
#include "estimation/joint_solver.h"
#include "estimation/junction_line_residual.h"
#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using testing::ExactObservation;
using testing::MakeGeometry;

struct Reference {
  double x[4];
  ceres::Solver::Summary summary;
};

// Ceres on the same problem from the same start (inside the bounds).
Reference CeresSolve(const CorridorObservation& obs, const SolverOptions& options,
                     const CorridorGeometry& start) {
  Reference ref{{start.yaw, start.pitch, start.offset, start.width}, {}};
  const FloorIntrinsics k{obs.fx, obs.fy, obs.cx, obs.cy, obs.camera_height};
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  std::unique_ptr<ceres::LossFunction> loss;
  if (options.loss == "huber") loss = std::make_unique<ceres::HuberLoss>(options.loss_scale);
  if (options.loss == "cauchy") loss = std::make_unique<ceres::CauchyLoss>(options.loss_scale);
  for (int side = -1; side <= 1; side += 2) {
    for (const auto& p : side < 0 ? obs.left : obs.right) {
      problem.AddResidualBlock(JunctionLineResidual::Create(k, p.x(), p.y(), side), loss.get(),
                               ref.x);
    }
  }
  const LmOptions& lm = options.lm;
  problem.SetParameterLowerBound(ref.x, 0, -lm.max_abs_yaw);
  problem.SetParameterUpperBound(ref.x, 0, lm.max_abs_yaw);
  problem.SetParameterLowerBound(ref.x, 1, -lm.max_abs_pitch);
  problem.SetParameterUpperBound(ref.x, 1, lm.max_abs_pitch);
  problem.SetParameterLowerBound(ref.x, 3, 0.05);
  ceres::Solve(LevenbergMarquardtOptions(lm), &problem, &ref.summary);
  return ref;
}

// Exact points of `truth` with Gaussian pixel noise, and every `outlier_every`-th point (0: none)
// moved by 15 to 40 pixels.
CorridorObservation NoisyObservation(const CorridorGeometry& truth, double sigma,
                                     int outlier_every, unsigned seed) {
  CorridorObservation obs = ExactObservation(truth, 25);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::uniform_real_distribution<double> jump(15.0, 40.0);
  int index = 0;
  for (auto* side : {&obs.left, &obs.right}) {
    for (auto& p : *side) {
      p += Eigen::Vector2d(noise(rng), noise(rng));
      if (outlier_every > 0 && ++index % outlier_every == 0) {
        p.y() += (index % 2 ? 1 : -1) * jump(rng);
      }
    }
  }
  return obs;
}

// The solve and the reference agree: parameters to 1e-6 (both stop within the LM tolerances of
// the same minimum, so only round-off separates them), the same convergence flag, iteration and
// residual-evaluation counts and final cost.
// Ceres solves the one problem on all points with the fixed loss scale: the joint solver's
// trimming and its loss scaled to the points' spread are off.
void ExpectSameAsCeres(const CorridorObservation& obs, const SolverOptions& trimmed_options,
                       const CorridorGeometry& start, const std::string& what) {
  SolverOptions options = trimmed_options;
  options.trim_sigmas = 0;
  options.loss_sigmas = 0;
  const Reference ref = CeresSolve(obs, options, start);
  ASSERT_TRUE(ref.summary.IsSolutionUsable()) << what << ": " << ref.summary.message;
  SolverSummary summary;
  const Status status = JointSolver(options).Solve(obs, &start, &summary);
  ASSERT_TRUE(status.ok()) << what << ": " << status.ToString();
  EXPECT_NEAR(summary.estimate.yaw, ref.x[0], 1e-6) << what;
  EXPECT_NEAR(summary.estimate.pitch, ref.x[1], 1e-6) << what;
  EXPECT_NEAR(summary.estimate.offset, ref.x[2], 1e-6) << what;
  EXPECT_NEAR(summary.estimate.width, ref.x[3], 1e-6) << what;
  EXPECT_EQ(summary.converged, ref.summary.termination_type == ceres::CONVERGENCE) << what;
  EXPECT_EQ(summary.iterations, static_cast<int>(ref.summary.iterations.size())) << what;
  EXPECT_EQ(summary.evaluations, ref.summary.num_residual_evaluations) << what;
  EXPECT_NEAR(summary.final_cost, ref.summary.final_cost, 1e-9 * (1 + ref.summary.final_cost))
      << what;
}

const std::vector<CorridorGeometry> kTruths = testing::ExampleCorridors(0.62);

// Starts away from the truth, as the closed form or the previous frame would give.
CorridorGeometry Perturbed(const CorridorGeometry& g, int i) {
  const double s = i % 2 ? 1.0 : -1.0;
  return MakeGeometry(g.yaw + s * 0.05, g.pitch - s * 0.03, g.offset + 0.2, g.width * 0.8,
                      g.camera_height);
}

class EveryLoss : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryLoss, MatchesCeresWithPixelNoise) {
  SolverOptions options;
  options.loss = GetParam();
  int i = 0;
  for (const auto& truth : kTruths) {
    for (double sigma : {0.3, 1.5}) {
      const CorridorObservation obs = NoisyObservation(truth, sigma, 0, 7 + i);
      ExpectSameAsCeres(obs, options, Perturbed(truth, i), "noise " + std::to_string(i));
      ++i;
    }
  }
}

TEST_P(EveryLoss, MatchesCeresWithOutliers) {
  SolverOptions options;
  options.loss = GetParam();
  int i = 0;
  for (const auto& truth : kTruths) {
    for (int every : {9, 4}) {
      const CorridorObservation obs = NoisyObservation(truth, 0.8, every, 31 + i);
      ExpectSameAsCeres(obs, options, Perturbed(truth, i), "outliers " + std::to_string(i));
      ++i;
    }
  }
}

TEST_P(EveryLoss, MatchesCeresWhenTheMinimumLiesOutsideTheBounds) {
  SolverOptions options;
  options.loss = GetParam();
  options.lm.max_abs_yaw = 0.08;    // the truth's yaw is 0.2
  options.lm.max_abs_pitch = 0.05;  // and its pitch 0.1
  const CorridorGeometry truth = MakeGeometry(-0.2, 0.1, -0.35, 3.1, 0.66);
  const CorridorObservation obs = NoisyObservation(truth, 0.5, 0, 3);
  const CorridorGeometry start = MakeGeometry(-0.05, 0.02, -0.2, 2.5, 0.66);
  ExpectSameAsCeres(obs, options, start, "yaw and pitch bounds");
  // Unbounded (the defaults), the minimum is outside the box; bounded, the solve stays in it and
  // ends on its pitch face.
  SolverSummary summary;
  ASSERT_TRUE(JointSolver(SolverOptions()).Solve(obs, &start, &summary).ok());
  EXPECT_GT(std::abs(summary.estimate.pitch), 0.05 + 0.02);
  ASSERT_TRUE(JointSolver(options).Solve(obs, &start, &summary).ok());
  EXPECT_LE(std::abs(summary.estimate.yaw), 0.08);
  EXPECT_EQ(summary.estimate.pitch, 0.05);

  // A corridor narrower than the 5 cm bound on the width.
  const CorridorGeometry narrow = MakeGeometry(0.02, 0.01, 0.0, 0.02, 0.66);
  const CorridorObservation narrow_obs = NoisyObservation(narrow, 0.05, 0, 5);
  const CorridorGeometry narrow_start = MakeGeometry(0.0, 0.0, 0.0, 0.5, 0.66);
  ExpectSameAsCeres(narrow_obs, SolverOptions(), narrow_start, "width bound");
  ASSERT_TRUE(JointSolver(SolverOptions()).Solve(narrow_obs, &narrow_start, &summary).ok());
  EXPECT_EQ(summary.estimate.width, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Losses, EveryLoss, ::testing::Values("none", "huber", "cauchy"));

TEST(JointSolverInputs, EmptyOrDegenerateSidesAreErrors) {
  const CorridorGeometry truth = kTruths[1];
  const CorridorGeometry start = Perturbed(truth, 0);
  JointSolver solver{SolverOptions()};
  SolverSummary summary;

  CorridorObservation one_side = ExactObservation(truth);
  one_side.right.clear();
  EXPECT_EQ(solver.Solve(one_side, &start, &summary).code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(solver.Solve(one_side, nullptr, &summary).code(), StatusCode::kInvalidArgument);

  CorridorObservation not_finite = ExactObservation(truth);
  not_finite.left[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(solver.Solve(not_finite, &start, &summary).code(), StatusCode::kInvalidArgument);

  // Every point of a side at one pixel: no line to fit.
  CorridorObservation collapsed = ExactObservation(truth);
  for (auto& p : collapsed.left) p = collapsed.left[0];
  for (auto& p : collapsed.right) p = collapsed.right[0];
  EXPECT_FALSE(solver.Solve(collapsed, nullptr, &summary).ok());

  // A start that is not a number: no residual can be evaluated there.
  CorridorGeometry bad_start = start;
  bad_start.offset = std::numeric_limits<double>::quiet_NaN();
  const Status status = solver.Solve(ExactObservation(truth), &bad_start, &summary);
  EXPECT_FALSE(status.ok());
  EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry) << status.ToString();
}

}  // namespace
}  // namespace corridor
