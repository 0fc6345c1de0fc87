// The solvers' evidence on generated corridors: with solver_evidence "edges", each junction's
// measured edge points lie on the generator's junction (TrueJunction, projected by hand), the
// observation carries them with their weights, and the width is the generator's; with "lines" no
// edge points are measured and the observation is the points sampled on the lines.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "corridor_depth/recover_depth.h"
#include "pipeline/solver_evidence.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

class SolverEvidenceTest : public ::testing::TestWithParam<int> {};

TEST_P(SolverEvidenceTest, EdgePointsLieOnTheGeneratorsJunctions) {
  const int width_px = GetParam();
  const Camera camera =
      Camera::FromHorizontalFov(width_px, width_px * 3 / 4, 80.0 * M_PI / 180, 0.7);
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, 2.2, 2.8, 3, synth::CameraPose{0.05, 0.03, 0.2, 0.7, 3.0});
  ASSERT_FALSE(frame.bgr.empty());
  RecoverDepthOptions options;
  options.solver_evidence = "edges";
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(frame.bgr, camera, options, &result).ok())
      << result.status.ToString();
  for (const int side : {-1, 1}) {
    const JunctionLine& line = side < 0 ? result.junctions.left : result.junctions.right;
    ASSERT_GE(static_cast<int>(line.edge_points.size()), options.points_per_line);
    ASSERT_EQ(line.edge_weights.size(), line.edge_points.size());
    const Eigen::Vector3d truth = testing_util::TrueJunction(frame.truth, camera, side);
    std::vector<double> distance;
    for (const Eigen::Vector2d& p : line.edge_points) {
      distance.push_back(std::abs(truth.dot(p.homogeneous())));
    }
    std::sort(distance.begin(), distance.end());
    EXPECT_LT(distance[distance.size() / 2], 0.3) << "side " << side;
    EXPECT_LT(distance[distance.size() * 9 / 10], 0.8) << "side " << side;
  }
  const CorridorObservation observation =
      ObservationFromJunctions(result.junctions, camera, options);
  EXPECT_EQ(observation.left.size(), result.junctions.left.edge_points.size());
  EXPECT_EQ(observation.right_weights.size(), result.junctions.right.edge_points.size());
  EXPECT_NEAR(result.geometry.width, frame.truth.width, 0.02 * frame.truth.width);

  options.solver_evidence = "lines";
  RecoverDepthResult lines;
  ASSERT_TRUE(RecoverDepth(frame.bgr, camera, options, &lines).ok()) << lines.status.ToString();
  EXPECT_TRUE(lines.junctions.left.edge_points.empty());
  const CorridorObservation sampled = ObservationFromJunctions(lines.junctions, camera, options);
  EXPECT_EQ(static_cast<int>(sampled.left.size()), options.points_per_line);
  EXPECT_TRUE(sampled.left_weights.empty());
}

INSTANTIATE_TEST_SUITE_P(ImageWidths, SolverEvidenceTest, ::testing::Values(640, 1280));

}  // namespace
}  // namespace corridor
