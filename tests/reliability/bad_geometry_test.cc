// Bad geometry: junction lines that are parallel (vanishing point at infinity), that meet below
// the points (vanishing point behind the camera), that meet far to the side (yaw near 90
// degrees), or that give a width outside the plausible bounds. The closed form, every solver
// behind DepthRecoverer::Reconstruct, and CheckPlausible must all say "implausible geometry",
// and no depth may come out.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "estimation/closed_form.h"
#include "pipeline/plausibility.h"
#include "corridor_depth/recover_depth.h"
#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

using testing::ExactObservation;
using testing::MakeGeometry;

// The camera of tests/support/exact_observation.h.
Camera ObservationCamera() {
  Camera c;
  c.image_width = 420;
  c.image_height = 360;
  c.fx = c.fy = 250;
  c.cx = 209.5;
  c.cy = 179.5;
  c.mount_height = 1.2;
  return c;
}

// Points from a to b, n of them.
std::vector<Eigen::Vector2d> Segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                     int n = 20) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < n; ++i) points.push_back(a + (b - a) * (i / (n - 1.0)));
  return points;
}

struct BadGeometry {
  const char* name;
  CorridorObservation observation;
  const char* closed_form_message;  // A part of SolveClosedForm's or CheckPlausible's message.
};

CorridorObservation WithLines(const std::vector<Eigen::Vector2d>& left,
                              const std::vector<Eigen::Vector2d>& right) {
  CorridorObservation obs = CorridorObservation::FromCamera(ObservationCamera());
  obs.left = left;
  obs.right = right;
  return obs;
}

std::vector<BadGeometry> BadGeometries() {
  return {
      {"parallel", WithLines(Segment({40, 350}, {140, 250}), Segment({300, 350}, {400, 250})),
       "parallel"},
      {"vanishing_point_behind", WithLines(Segment({100, 200}, {180, 340}), Segment({320, 200}, {240, 340})),
       "not on the floor"},
      // Yaw 1.5 rad (86 degrees): the vanishing point is far right of the image.
      {"yaw_near_90", ExactObservation(MakeGeometry(1.5, 0.05, 0.0, 2.0, 1.2), 20, 30, 200),
       "yaw 1.5 rad is beyond"},
      {"too_wide", ExactObservation(MakeGeometry(0.05, 0.08, 0.0, 30.0, 1.2), 20, 20, 60),
       "width 30"},
      {"too_narrow", ExactObservation(MakeGeometry(0.05, 0.08, 0.0, 0.3, 1.2), 20, 2, 12),
       "width 0.3"},
  };
}

TEST(BadGeometry, ClosedFormOrCheckPlausibleRejects) {
  for (const BadGeometry& bad : BadGeometries()) {
    CorridorGeometry geometry;
    Status status = SolveClosedForm(bad.observation, &geometry);
    if (status.ok()) status = CheckPlausible(geometry, RecoverDepthOptions());
    EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry) << bad.name << ": "
                                                               << status.ToString();
    EXPECT_NE(status.message().find(bad.closed_form_message), std::string::npos)
        << bad.name << ": " << status.ToString();
  }
}

// Junction lines through the observation's first and last points on each side.
JunctionPair PairFrom(const CorridorObservation& obs) {
  JunctionPair pair;
  const auto line = [](const std::vector<Eigen::Vector2d>& points) {
    JunctionLine l;
    l.near_end = points.front();
    l.far_end = points.back();
    const Eigen::Vector2d d = (l.far_end - l.near_end).normalized();
    l.line = Eigen::Vector3d(-d.y(), d.x(), 0);
    l.line.z() = -l.line.head<2>().dot(l.near_end);
    l.confidence = 1;
    return l;
  };
  pair.left = line(obs.left);
  pair.right = line(obs.right);
  return pair;
}

class BadGeometryBySolver : public ::testing::TestWithParam<const char*> {};

TEST_P(BadGeometryBySolver, ReconstructSaysImplausibleAndGivesNoDepth) {
  RecoverDepthOptions options;
  options.solver = GetParam();
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
  for (const BadGeometry& bad : BadGeometries()) {
    RecoverDepthResult result;
    result.junctions = PairFrom(bad.observation);
    const Status status = recoverer->Reconstruct(ObservationCamera(), &result);
    RecordProperty(bad.name, status.ToString());
    EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry)
        << bad.name << ": " << status.ToString() << " estimate "
        << result.solver_summary.estimate.ToString();
    EXPECT_TRUE(result.depth.empty()) << bad.name;
    EXPECT_FALSE(result.has_geometry) << bad.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, BadGeometryBySolver,
                         ::testing::Values("closed_form", "grid", "lm", "joint", "closed_form+lm",
                                           "closed_form+joint"));

TEST(BadGeometry, CheckPlausibleNamesWhatIsImplausible) {
  const RecoverDepthOptions defaults;
  struct Case {
    CorridorGeometry geometry;
    const char* message;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Case cases[] = {
      {MakeGeometry(0, 0.1, 0, 0.49, 1.2), "width 0.49 m is narrower than min_corridor_width 0.5 m"},
      {MakeGeometry(0, 0.1, 0, 5.5, 1.2), "width 5.5 m is wider than max_corridor_width 5 m"},
      {MakeGeometry(1.3, 0.1, 0, 2, 1.2), "yaw 1.3 rad"},
      {MakeGeometry(-1.55, 0.1, 0, 2, 1.2), "yaw -1.55 rad"},
      {MakeGeometry(0, 0.9, 0, 2, 1.2), "pitch 0.9 rad"},
      {MakeGeometry(0, 0.1, 1.5, 2, 1.2), "not between the walls"},
      {MakeGeometry(nan, 0.1, 0, 2, 1.2), "non-finite"},
      {MakeGeometry(0, 0.1, 0, std::numeric_limits<double>::infinity(), 1.2), "non-finite"},
  };
  for (const Case& c : cases) {
    const Status status = CheckPlausible(c.geometry, defaults);
    EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry) << c.message;
    EXPECT_NE(status.message().find(c.message), std::string::npos) << status.ToString();
  }
  EXPECT_TRUE(CheckPlausible(MakeGeometry(0.1, 0.1, 0.2, 2.0, 1.2), defaults).ok());
  EXPECT_TRUE(CheckPlausible(MakeGeometry(0, 0.1, 0, 4.9, 1.2), defaults).ok());
  RecoverDepthOptions narrow;
  narrow.min_width = 1.0;
  narrow.max_width = 3.0;
  EXPECT_EQ(CheckPlausible(MakeGeometry(0, 0.1, 0, 4.0, 1.2), narrow).code(),
            StatusCode::kImplausibleGeometry);
  RecoverDepthOptions hall;
  hall.max_width = 8.0;
  EXPECT_TRUE(CheckPlausible(MakeGeometry(0, 0.1, 0, 6.0, 1.2), hall).ok());
}

// A 6 m wide corridor, its junctions exact: refused by default (wider than max_corridor_width),
// recovered at 6 m when the bound is raised for a hall.
TEST(BadGeometry, WiderThanACorridorIsRefusedUnlessTheBoundIsRaised) {
  const CorridorGeometry truth = MakeGeometry(0.05, 0.08, 0.3, 6.0, 1.2);
  const CorridorObservation obs = ExactObservation(truth, 20, 20, 60);
  for (const double max_width : {RecoverDepthOptions().max_width, 8.0}) {
    RecoverDepthOptions options;
    options.max_width = max_width;
    std::unique_ptr<DepthRecoverer> recoverer;
    ASSERT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
    RecoverDepthResult result;
    result.junctions = PairFrom(obs);
    const Status status = recoverer->Reconstruct(ObservationCamera(), &result);
    if (max_width < 6.0) {
      EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry) << status.ToString();
      EXPECT_NE(status.message().find("wider than max_corridor_width"), std::string::npos)
          << status.ToString();
      EXPECT_TRUE(result.depth.empty());
    } else {
      ASSERT_TRUE(status.ok()) << status.ToString();
      EXPECT_NEAR(result.geometry.width, 6.0, 0.06);
    }
  }
}

// A solver stopped at the edge of its range (here: the grid's widest corridor, 10 m, for a 30 m
// one) gives lines that miss the junctions: CheckLineFit says so; the true geometry passes.
TEST(BadGeometry, CheckLineFitRejectsAnEstimateThatMissesTheLines) {
  const CorridorGeometry truth = MakeGeometry(0.05, 0.08, 0.0, 30.0, 1.2);
  const CorridorObservation obs = ExactObservation(truth, 20, 20, 60);
  const RecoverDepthOptions options;
  EXPECT_TRUE(CheckLineFit(truth, obs, ObservationCamera(), options).ok());
  CorridorGeometry clipped = truth;
  clipped.width = 10.0;
  const Status status = CheckLineFit(clipped, obs, ObservationCamera(), options);
  EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry);
  EXPECT_NE(status.message().find("does not explain the junction lines"), std::string::npos)
      << status.ToString();
}

}  // namespace
}  // namespace corridor
