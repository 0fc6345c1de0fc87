// The maximum-likelihood solvers' cap on point weights (estimation/capped_weights.h,
// SolverOptions::max_weight_ratio): hand-computed capped weights, and, on exact junction points
// (tests/support/exact_observation.h, Eigen's own projection) with a few strong points on a
// second edge beside the left junction, a fit that caps their weight lands nearer the true width
// than one that takes it as given.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/solver.h"
#include "estimation/capped_weights.h"
#include "tests/support/exact_observation.h"
#include "tests/support/weights_only_width.h"

namespace corridor {
namespace {

using testing::ExactObservation;

TEST(CappedWeightsTest, EachSideIsCappedAtItsMedianTimesTheRatioThenScaledToAMeanOfOne) {
  CorridorObservation obs = ExactObservation(testing::ExampleCorridors()[0], 5, 2.0, 12.0);
  obs.left_weights = {1, 1, 1, 8, 0.5};  // Median 1: the 8 is capped at 2.
  CorridorObservation capped;
  ASSERT_TRUE(CapWeights(obs, 2.0, &capped));
  // Capped: {1, 1, 1, 2, 0.5}, sum 5.5, times 5 / 5.5.
  const std::vector<double> expected = {10.0 / 11, 10.0 / 11, 10.0 / 11, 20.0 / 11, 5.0 / 11};
  ASSERT_EQ(capped.left_weights.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(capped.left_weights[i], expected[i], 1e-12) << i;
  }
  EXPECT_TRUE(capped.right_weights.empty());  // No weights: every weight 1, as before.
  ASSERT_EQ(capped.left.size(), obs.left.size());
  EXPECT_EQ(capped.left[3], obs.left[3]);
  EXPECT_EQ(capped.right, obs.right);
  EXPECT_EQ(capped.fx, obs.fx);
  EXPECT_EQ(capped.camera_height, obs.camera_height);
}

TEST(CappedWeightsTest, NoWeightsOrNoRatioLeaveTheObservationAsGiven) {
  CorridorObservation obs = ExactObservation(testing::ExampleCorridors()[0], 5, 2.0, 12.0);
  CorridorObservation capped;
  EXPECT_FALSE(CapWeights(obs, 2.0, &capped));
  obs.left_weights = {1, 1, 1, 8, 0.5};
  EXPECT_FALSE(CapWeights(obs, 0.0, &capped));
}

// Exact points; on the left, every other point of the far third 1 px below the junction (a
// second edge) with four times the others' weight, as the strongest edge points near the
// vanishing point often are.
CorridorObservation StrongSecondEdge(const CorridorGeometry& truth) {
  CorridorObservation obs = ExactObservation(truth, 60, 2.0, 12.0);
  obs.left_weights.assign(obs.left.size(), 1.0);
  for (size_t i = 2 * obs.left.size() / 3; i < obs.left.size(); i += 2) {
    obs.left[i].y() += 1.0;
    obs.left_weights[i] = 4.0;
  }
  return obs;
}

TEST(CappedWeightsTest, JointAndLmLandNearerTheTruthWithTheStrongPointsCapped) {
  for (const CorridorGeometry& truth : testing::ExampleCorridors()) {
    const CorridorObservation obs = StrongSecondEdge(truth);
    for (const std::string solver : {"joint", "lm"}) {
      SCOPED_TRACE(solver + ", width " + std::to_string(truth.width));
      const double as_given = testing::WeightsOnlyWidthError(solver, obs, truth, 0.0);
      const double capped = testing::WeightsOnlyWidthError(solver, obs, truth, 2.0);
      EXPECT_GT(as_given, 1e-3);  // The second edge's pull is measurable.
      EXPECT_LT(capped, 0.75 * as_given);
    }
  }
}

}  // namespace
}  // namespace corridor
