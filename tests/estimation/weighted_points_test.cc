// Point weights in every solver: where some junction points are weak and off the junction (a
// faint parallel edge's pixels, a shadow), the fit that weighs them by their small weight recovers
// the true width, the fit that counts them as much as the rest does not. Truth: the hand-set
// geometry, its points projected with Eigen's rotations (tests/support/exact_observation.h), not
// with the solvers'. Also the observation's checks of the weights.

#include <vector>
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "corridor_depth/solver.h"
#include "tests/support/exact_observation.h"
#include "tests/support/weights_only_width.h"

namespace corridor {
namespace {

using testing::ExactObservation;

const std::vector<CorridorGeometry> kTruths = testing::ExampleCorridors();

// The truth's points with Gaussian noise of 0.1 px; two in five points of the left side moved
// `shift` px to the left (a fainter parallel edge's pixels) and given weight `weak`; the other
// points weight 1.
CorridorObservation WeakShiftedObservation(const CorridorGeometry& truth, double shift,
                                           double weak, unsigned seed) {
  CorridorObservation obs = ExactObservation(truth, 60, 2.0, 12.0);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.1);
  for (const int side : {-1, 1}) {
    auto& points = side < 0 ? obs.left : obs.right;
    auto& weights = side < 0 ? obs.left_weights : obs.right_weights;
    weights.assign(points.size(), 1.0);
    for (size_t i = 0; i < points.size(); ++i) {
      points[i] += Eigen::Vector2d(noise(rng), noise(rng));
      if (side < 0 && i % 5 < 2) {
        points[i].x() -= shift;
        weights[i] = weak;
      }
    }
  }
  return obs;
}

TEST(WeightedPointsTest, EverySolverRecoversTheWidthFromWeightedPoints) {
  unsigned seed = 7;
  for (const auto& truth : kTruths) {
    const CorridorObservation weighted = WeakShiftedObservation(truth, 8.0, 0.01, seed);
    CorridorObservation unweighted = weighted;
    unweighted.left_weights.clear();
    unweighted.right_weights.clear();
    for (const std::string name : {"closed_form", "lm", "joint", "grid"}) {
      const double with = testing::WeightsOnlyWidthError(name, weighted, truth);
      const double without = testing::WeightsOnlyWidthError(name, unweighted, truth);
      // Weighted within 0.2% (0.15% or less in every case here); unweighted 0.21-1.6% off.
      EXPECT_LT(with, 0.002) << name << " width " << truth.width;
      EXPECT_GT(without, 0.002) << name << " width " << truth.width;
      EXPECT_LT(with, 0.5 * without) << name << " width " << truth.width;
    }
    ++seed;
  }
}

TEST(WeightedPointsTest, UnitWeightsAreNoWeights) {
  for (const auto& truth : kTruths) {
    CorridorObservation obs = WeakShiftedObservation(truth, 3.0, 1.0, 3);
    CorridorObservation none = obs;
    none.left_weights.clear();
    none.right_weights.clear();
    for (const std::string name : {"closed_form", "lm", "joint", "grid"}) {
      EXPECT_NEAR(testing::WeightsOnlyWidthError(name, obs, truth),
                  testing::WeightsOnlyWidthError(name, none, truth), 1e-9)
          << name;
    }
  }
}

TEST(WeightedPointsTest, BadWeightsAreRejected) {
  CorridorObservation obs = ExactObservation(kTruths[0], 10);
  std::string why;
  ASSERT_TRUE(obs.Check(&why)) << why;
  obs.left_weights.assign(9, 1.0);  // Not one per point.
  EXPECT_FALSE(obs.Check(&why));
  EXPECT_NE(why.find("weights"), std::string::npos);
  obs.left_weights.assign(10, 1.0);
  obs.left_weights[3] = -1;
  EXPECT_FALSE(obs.Check(&why));
  obs.left_weights[3] = std::nan("");
  EXPECT_FALSE(obs.Check(&why));
  obs.left_weights.assign(10, 0.0);
  obs.left_weights[0] = 1;  // One positive weight: a line needs two.
  EXPECT_FALSE(obs.Check(&why));
  obs.left_weights[1] = 1;
  EXPECT_TRUE(obs.Check(&why)) << why;
  std::unique_ptr<CorridorSolver> solver;
  ASSERT_TRUE(CreateSolver("joint", SolverOptions(), &solver).ok());
  SolverSummary summary;
  obs.right_weights.assign(3, 1.0);
  EXPECT_EQ(solver->Solve(obs, nullptr, &summary).code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace corridor
