#include "estimation/closed_form.h"

#include <gtest/gtest.h>

#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using testing::ExactObservation;
using testing::MakeGeometry;

TEST(ClosedFormTest, RecoversExactGeometry) {
  for (const auto& truth : {MakeGeometry(0.0, 0.0, 0.0, 2.0, 0.66),
                            MakeGeometry(0.15, 0.08, 0.3, 2.6, 0.62),
                            MakeGeometry(-0.3, -0.1, -0.5, 3.1, 1.2)}) {
    CorridorGeometry g;
    ASSERT_TRUE(SolveClosedForm(ExactObservation(truth), &g).ok());
    EXPECT_NEAR(g.yaw, truth.yaw, 1e-9);
    EXPECT_NEAR(g.pitch, truth.pitch, 1e-9);
    EXPECT_NEAR(g.offset, truth.offset, 1e-9);
    EXPECT_NEAR(g.width, truth.width, 1e-9);
  }
}

TEST(ClosedFormTest, FitImageLineThroughHandPoints) {
  // Points on v = 2u + 1, i.e. 2u - v + 1 = 0, normalised by sqrt(5).
  Eigen::Vector3d line;
  ASSERT_TRUE(FitImageLine({{0, 1}, {1, 3}, {2, 5}}, &line));
  const double s = line.x() > 0 ? 1 : -1;
  EXPECT_NEAR(s * line.x(), 2 / std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(s * line.y(), -1 / std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(s * line.z(), 1 / std::sqrt(5.0), 1e-12);
  EXPECT_FALSE(FitImageLine({{1, 1}, {1, 1}}, &line));
}

TEST(ClosedFormTest, ParallelLinesAreImplausible) {
  CorridorObservation obs = ExactObservation(MakeGeometry(0, 0, 0, 2, 0.66));
  obs.left = {{10, 300}, {20, 290}, {30, 280}};
  obs.right = {{110, 300}, {120, 290}, {130, 280}};
  CorridorGeometry g;
  const Status status = SolveClosedForm(obs, &g);
  EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry);
  EXPECT_NE(status.message().find("parallel"), std::string::npos) << status.message();
}

TEST(ClosedFormTest, LinesMeetingBelowArePointsAboveTheHorizon) {
  // The lines diverge upward: their intersection lies below, so the points are not on a floor
  // seen by this camera.
  CorridorObservation obs = ExactObservation(MakeGeometry(0, 0, 0, 2, 0.66));
  obs.left = {{200, 300}, {150, 250}, {100, 200}};
  obs.right = {{220, 300}, {270, 250}, {320, 200}};
  CorridorGeometry g;
  EXPECT_EQ(SolveClosedForm(obs, &g).code(), StatusCode::kImplausibleGeometry);
}

TEST(ClosedFormTest, TooFewPointsIsInvalid) {
  CorridorObservation obs = ExactObservation(MakeGeometry(0, 0, 0, 2, 0.66));
  obs.left.resize(1);
  CorridorGeometry g;
  EXPECT_EQ(SolveClosedForm(obs, &g).code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace corridor
