#include "corridor_depth/solver.h"

#include <vector>
#include <random>

#include <gtest/gtest.h>

#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using testing::ExactObservation;
using testing::MakeGeometry;

const std::vector<CorridorGeometry> kTruths = testing::ExampleCorridors(0.62);

struct Tolerance {
  double angle, metric;  // rad, m
};

// Every solver recovers the truth from exact edge points: the iterative ones to 1e-4 rad and
// 1 mm; the grid to within its finest step (2 refinement levels of /10 below 0.05 rad) in the
// angles, and in offset and width to within the finest 0.5 mm step plus what a one-step angle
// error moves them (hence 3 steps).
Tolerance ToleranceFor(const std::string& name) {
  if (name.find("grid") != std::string::npos) return {0.05 / 100 * (1 + 1e-6), 3 * 0.05 / 100};
  return {1e-4, 1e-3};
}

class EverySolver : public ::testing::TestWithParam<std::string> {};

TEST_P(EverySolver, RecoversTruthFromExactEdgePoints) {
  std::unique_ptr<CorridorSolver> solver;
  ASSERT_TRUE(CreateSolver(GetParam(), SolverOptions(), &solver).ok());
  const Tolerance tol = ToleranceFor(GetParam());
  for (const auto& truth : kTruths) {
    SolverSummary summary;
    const Status status = solver->Solve(ExactObservation(truth), nullptr, &summary);
    ASSERT_TRUE(status.ok()) << status.ToString();
    EXPECT_NEAR(summary.estimate.yaw, truth.yaw, tol.angle) << GetParam();
    EXPECT_NEAR(summary.estimate.pitch, truth.pitch, tol.angle) << GetParam();
    EXPECT_NEAR(summary.estimate.offset, truth.offset, tol.metric) << GetParam();
    EXPECT_NEAR(summary.estimate.width, truth.width, tol.metric) << GetParam();
    EXPECT_GT(summary.evaluations, 0);
    EXPECT_EQ(summary.solver_name, GetParam());
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, EverySolver,
                         ::testing::Values("grid", "closed_form", "lm", "joint",
                                           "closed_form+lm", "closed_form+grid", "grid+joint"),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name) c = c == '+' ? '_' : c;
                           return name;
                         });

// With 20% gross outliers among the edge points, a robust loss keeps the width within 1%.
void ExpectRobustToOutliers(const std::string& solver_name, unsigned seed) {
  const CorridorGeometry truth = MakeGeometry(0.08, 0.05, 0.2, 2.4, 0.62);
  CorridorObservation obs = ExactObservation(truth, 40, 2.0, 15.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-40.0, 40.0);
  for (auto* side : {&obs.left, &obs.right}) {
    for (size_t i = 0; i < side->size(); i += 5) (*side)[i].x() += shift(rng);
  }
  SolverOptions options;
  options.loss = "cauchy";
  options.loss_scale = 1.0;
  std::unique_ptr<CorridorSolver> solver;
  ASSERT_TRUE(CreateSolver(solver_name, options, &solver).ok());
  SolverSummary summary;
  ASSERT_TRUE(solver->Solve(obs, nullptr, &summary).ok());
  EXPECT_NEAR(summary.estimate.width, truth.width, 0.01 * truth.width) << solver_name;
}

TEST(LmSolverTest, RobustLossSurvivesOutliers) { ExpectRobustToOutliers("lm", 7); }

// Without an initial estimate "lm" starts from the closed form's: the same answer as when given
// the closed form's estimate, and the truth from exact points at poses far from the
// alternation's own start (zero yaw and offset, a 2 m width), as it was from that start.
TEST(LmSolverTest, StartsFromTheClosedForm) {
  SolverOptions from_default;
  from_default.lm.start_from_closed_form = false;
  std::unique_ptr<CorridorSolver> lm, lm_from_default, closed_form;
  ASSERT_TRUE(CreateSolver("lm", SolverOptions(), &lm).ok());
  ASSERT_TRUE(CreateSolver("lm", from_default, &lm_from_default).ok());
  ASSERT_TRUE(CreateSolver("closed_form", SolverOptions(), &closed_form).ok());
  for (const double yaw : {-0.35, 0.25}) {
    for (const double width : {1.2, 4.5}) {
      for (const double side : {-0.3, 0.25}) {
        const CorridorGeometry truth = MakeGeometry(yaw, 0.08 - 0.1 * side, side * width, width,
                                                    0.66);
        CorridorObservation observation = ExactObservation(truth);
        // Points a pixel off their lines, alternately, so that no two starts end identically by
        // chance of an exact fit.
        for (auto* points : {&observation.left, &observation.right}) {
          for (size_t i = 0; i < points->size(); ++i) (*points)[i].x() += i % 2 ? 0.5 : -0.5;
        }
        SolverSummary start, alone, given, from_zero;
        ASSERT_TRUE(closed_form->Solve(observation, nullptr, &start).ok());
        ASSERT_TRUE(lm->Solve(observation, nullptr, &alone).ok());
        ASSERT_TRUE(lm->Solve(observation, &start.estimate, &given).ok());
        ASSERT_TRUE(lm_from_default->Solve(observation, nullptr, &from_zero).ok());
        EXPECT_EQ(alone.estimate.width, given.estimate.width);
        EXPECT_EQ(alone.estimate.yaw, given.estimate.yaw);
        EXPECT_EQ(alone.iterations, given.iterations);
        EXPECT_NEAR(alone.estimate.yaw, truth.yaw, 2e-3);
        EXPECT_NEAR(alone.estimate.width, truth.width, 0.01 * truth.width);
        EXPECT_NEAR(from_zero.estimate.width, alone.estimate.width, 1e-3 * truth.width);
      }
    }
  }
}

TEST(JointSolverTest, RobustLossSurvivesOutliers) { ExpectRobustToOutliers("closed_form+joint", 11); }

TEST(SolverFactoryTest, UnknownNameListsValidNames) {
  std::unique_ptr<CorridorSolver> solver;
  const Status status = CreateSolver("newton", SolverOptions(), &solver);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("grid"), std::string::npos) << status.message();
  EXPECT_NE(status.message().find("closed_form"), std::string::npos) << status.message();
  EXPECT_EQ(CreateSolver("", SolverOptions(), &solver).code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(CreateSolver("lm+", SolverOptions(), &solver).code(), StatusCode::kInvalidArgument);
}

TEST(SolverFactoryTest, BadOptionsRejectedBeforeWork) {
  SolverOptions options;
  options.grid.yaw_step = 0;
  std::unique_ptr<CorridorSolver> solver;
  const Status status = CreateSolver("grid", options, &solver);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("yaw step"), std::string::npos) << status.message();
}

}  // namespace
}  // namespace corridor
