// The joint solver's trimming: a second line's points mixed into one junction's pull the plain
// least-squares fit (and a fixed-scale Huber fit) off the true width; the fit that drops points
// far beyond the side's own spread recovers it. Truth: the hand-set geometry, its points projected
// with Eigen's rotations (tests/support/exact_observation.h), not with the solver's.

#include <vector>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "estimation/joint_solver.h"
#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using testing::ExactObservation;
using testing::MakeGeometry;

// The truth's points with Gaussian pixel noise, and on the left, `extra` points of a second floor
// line parallel to the junction `inset` metres nearer the camera (a baseboard's top, a runner's
// edge), over the near part of the view.
CorridorObservation MixedObservation(const CorridorGeometry& truth, double sigma, int extra,
                                     double inset, unsigned seed) {
  CorridorObservation obs = ExactObservation(truth, 30, 2.0, 12.0);
  // The same rotation, the left wall `inset` nearer, the right wall where it is.
  const CorridorGeometry other = MakeGeometry(truth.yaw, truth.pitch, truth.offset - inset / 2,
                                              truth.width - inset, truth.camera_height);
  const CorridorObservation second = ExactObservation(other, extra, 2.0, 6.0);
  obs.left.insert(obs.left.end(), second.left.begin(), second.left.end());
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (auto* side : {&obs.left, &obs.right}) {
    for (auto& p : *side) p += Eigen::Vector2d(noise(rng), noise(rng));
  }
  return obs;
}

double WidthError(const SolverOptions& options, const CorridorObservation& obs,
                  const CorridorGeometry& truth) {
  SolverSummary summary;
  const Status status = JointSolver(options).Solve(obs, nullptr, &summary);
  EXPECT_TRUE(status.ok()) << status.ToString();
  return std::abs(summary.estimate.width - truth.width) / truth.width;
}

const std::vector<CorridorGeometry> kTruths = testing::ExampleCorridors(1.2);

TEST(JointTrimTest, ASecondLinesPointsAreDroppedAndTheWidthRecovered) {
  SolverOptions plain;
  plain.loss = "none";
  plain.trim_sigmas = 0;
  SolverOptions huber;  // the default loss at the fixed scale, no trimming
  huber.trim_sigmas = 0;
  huber.loss_sigmas = 0;
  const SolverOptions trimmed;  // the defaults: Huber, then trimming
  ASSERT_GT(trimmed.trim_sigmas, 0);
  unsigned seed = 1;
  for (const auto& truth : kTruths) {
    for (double sigma : {0.3, 0.8}) {
      const CorridorObservation obs = MixedObservation(truth, sigma, 12, 0.3, seed++);
      const double plain_error = WidthError(plain, obs, truth);
      const double huber_error = WidthError(huber, obs, truth);
      const double trimmed_error = WidthError(trimmed, obs, truth);
      EXPECT_GT(plain_error, 0.03) << "sigma " << sigma << " seed " << seed;
      EXPECT_LT(trimmed_error, huber_error) << "sigma " << sigma << " seed " << seed;
      EXPECT_LT(trimmed_error, 0.006) << "sigma " << sigma << " seed " << seed;
    }
  }
}

TEST(JointTrimTest, PointsOnTheirLinesGiveTheUntrimmedFit) {
  // Noise alone: trimming drops at most the rare tail point, so the two fits nearly agree; exact
  // points are all kept, so the fits are the same.
  SolverOptions untrimmed;
  untrimmed.trim_sigmas = 0;
  const SolverOptions trimmed;
  for (const auto& truth : kTruths) {
    const CorridorObservation exact = ExactObservation(truth, 30);
    SolverSummary a, b;
    ASSERT_TRUE(JointSolver(untrimmed).Solve(exact, nullptr, &a).ok());
    ASSERT_TRUE(JointSolver(trimmed).Solve(exact, nullptr, &b).ok());
    EXPECT_EQ(a.estimate.width, b.estimate.width);
    EXPECT_EQ(a.estimate.offset, b.estimate.offset);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_NEAR(b.estimate.width, truth.width, 1e-6 * truth.width);

    const CorridorObservation noisy = MixedObservation(truth, 0.5, 0, 0.0, 11);
    ASSERT_TRUE(JointSolver(untrimmed).Solve(noisy, nullptr, &a).ok());
    ASSERT_TRUE(JointSolver(trimmed).Solve(noisy, nullptr, &b).ok());
    EXPECT_NEAR(a.estimate.width, b.estimate.width, 0.003 * truth.width);
    EXPECT_NEAR(b.estimate.width, truth.width, 0.01 * truth.width);
  }
}

TEST(JointTrimTest, NegativeOrNonFiniteTrimIsRejected) {
  SolverOptions options;
  std::string why;
  options.trim_sigmas = -1;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("trim_sigmas"), std::string::npos);
  options.trim_sigmas = std::nan("");
  EXPECT_FALSE(options.Check(&why));
  options.trim_sigmas = 0;
  EXPECT_TRUE(options.Check(&why)) << why;
}

}  // namespace
}  // namespace corridor
