// RefitJunctionAtFullResolution against the generator's junctions: a coarse line 1.5 px and half a
// degree off (as a fit on a halved image may be) comes back onto the true floor/wall junction of a
// rendered 1280x720 corridor, projected by hand from the true geometry.
#include "perception/junction_refit.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "corridor_depth/camera.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

// The point of `line` at image row v.
Eigen::Vector2d AtRow(const Eigen::Vector3d& line, double v) {
  return {-(line.y() * v + line.z()) / line.x(), v};
}

// Largest distance from the true line of `line`'s points at rows v0..v1.
double LargestDistance(const Eigen::Vector3d& line, const Eigen::Vector3d& truth, double v0,
                       double v1) {
  double worst = 0;
  for (double v = v0; v <= v1; v += 1) {
    worst = std::max(worst, std::abs(truth.dot(AtRow(line, v).homogeneous())));
  }
  return worst;
}

TEST(JunctionRefitTest, ACoarseLineComesBackOntoTheTrueJunction) {
  const Camera camera = Camera::FromHorizontalFov(1280, 720, 80.0 * M_PI / 180, 0.66);
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, 2.2, 2.7, 7, synth::CameraPose{0.04, 0.05, 0.2, 0.66, 3.0}, 0.0);
  ASSERT_FALSE(frame.bgr.empty());
  for (const int side : {-1, 1}) {
    const Eigen::Vector3d truth = testing_util::TrueJunction(frame.truth, camera, side);
    // The junction's stretch below the horizon, rows v_far to v_near, inside the image.
    double v_far = 430, v_near = 700;
    while (AtRow(truth, v_near).x() < 10 || AtRow(truth, v_near).x() > camera.image_width - 10) {
      v_near -= 1;
    }
    ASSERT_GT(v_near - v_far, 150) << "premise: a long stretch in view";
    // The coarse line: through points 1.5 px and 0.5 px beside the true ones, normal kept.
    const Eigen::Vector2d n = truth.head<2>();
    const Eigen::Vector2d near = AtRow(truth, v_near) + 1.5 * n;
    const Eigen::Vector2d far = AtRow(truth, v_far) - 0.5 * n;
    JunctionLine line;
    line.line = near.homogeneous().cross(far.homogeneous());
    line.line /= line.line.head<2>().norm();
    if (line.line.dot(truth) < 0) line.line = -line.line;
    line.near_end = near;
    line.far_end = far;
    ASSERT_GT(LargestDistance(line.line, truth, v_far, v_near), 1.4) << "premise: coarse";
    JunctionRefitOptions options;
    options.reach_px = 4;
    // The detector's least threshold (0.4 of Canny's least high threshold): the right junction
    // meets a dark baseboard, a step of about ten grey levels in the red channel.
    options.threshold = 16;
    ASSERT_TRUE(RefitJunctionAtFullResolution(frame.bgr, options, &line)) << side;
    EXPECT_LT(LargestDistance(line.line, truth, v_far, v_near), 0.35) << side;
    EXPECT_GT(line.line.head<2>().dot(n), 0) << "the normal keeps its direction";
    // The ends lie on the new line, near the old ones.
    EXPECT_LT(std::abs(line.line.dot(line.near_end.homogeneous())), 1e-9);
    EXPECT_LT((line.near_end - near).norm(), 2.0);
    EXPECT_GE(line.support.size(), 100u);
  }
}

TEST(JunctionRefitTest, AFlatImageOrAnotherTypeLeavesTheLine) {
  JunctionLine line;
  line.line = Eigen::Vector3d(0.8, 0.6, -300);
  line.near_end = Eigen::Vector2d(0, 500);
  line.far_end = Eigen::Vector2d(300, 100);
  const JunctionLine before = line;
  const cv::Mat flat(480, 640, CV_8UC3, cv::Scalar(90, 100, 110));
  EXPECT_FALSE(RefitJunctionAtFullResolution(flat, JunctionRefitOptions(), &line));
  EXPECT_EQ(line.line, before.line);
  EXPECT_EQ(line.near_end, before.near_end);
  const cv::Mat grey(480, 640, CV_8U, cv::Scalar(0));
  EXPECT_FALSE(RefitJunctionAtFullResolution(grey, JunctionRefitOptions(), &line));
  EXPECT_FALSE(RefitJunctionAtFullResolution(cv::Mat(), JunctionRefitOptions(), &line));
  EXPECT_EQ(line.line, before.line);
}

}  // namespace
}  // namespace corridor
