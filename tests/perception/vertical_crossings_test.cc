// Vertical edges and junctions on generated corridors with a door every few metres: the door
// frames stop at the true floor/wall junction, and cross a horizontal line of the wall (where a
// handrail or chair rail would run) that a wrong geometry takes for the junction.
#include "perception/vertical_crossings.h"

#include <cmath>

#include <gtest/gtest.h>

#include "synth/corridor_renderer.h"
#include "synth/corridor_scene.h"

namespace corridor {
namespace {

// The visible extent of the junction of `side` that `g` puts on the wall: the projections of
// its points from `near` to `far` metres along the corridor (hand projection, P_C = R P_W).
JunctionLine Extent(const CorridorGeometry& g, const Camera& camera, int side, double near,
                    double far) {
  const double x = side == 0 ? -g.LeftDistance() : g.RightDistance();
  const auto project = [&](double z) {
    const double cp = std::cos(g.yaw), sp = std::sin(g.yaw), ct = std::cos(g.pitch),
                 st = std::sin(g.pitch);
    const double y = g.camera_height;
    const double xc = cp * x + sp * z;
    const double yc = st * sp * x + ct * y - st * cp * z;
    const double zc = -ct * sp * x + st * y + ct * cp * z;
    return Eigen::Vector2d(camera.fx * xc / zc + camera.cx, camera.fy * yc / zc + camera.cy);
  };
  JunctionLine line;
  line.near_end = project(near);
  line.far_end = project(far);
  return line;
}

class VerticalCrossingsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    camera_ = Camera::FromHorizontalFov(640, 480, 70.0 * M_PI / 180, 1.2);
    synth::SceneOptions scene;
    scene.width = 2.4;
    scene.door_density = 1.0;
    scene.seed = 5;
    pose_.height = 1.2;
    pose_.pitch = 0.08;
    pose_.yaw = 0.05;
    pose_.distance = 3.0;
    ASSERT_TRUE(synth::RenderFrame(synth::BuildScene(scene), camera_, pose_, &frame_).ok());
  }
  Camera camera_;
  synth::CameraPose pose_;
  synth::Frame frame_;
};

TEST_F(VerticalCrossingsTest, DoorFramesStopAtTheTrueJunction) {
  for (int side = 0; side < 2; ++side) {
    const JunctionLine line = Extent(frame_.truth, camera_, side, 2.0, 14.0);
    const VerticalCrossings c = CountVerticalCrossings(frame_.bgr, camera_, 1, frame_.truth, side,
                                                       line, VerticalCrossingOptions());
    EXPECT_GE(c.reaching, 2) << "side " << side;
    EXPECT_LE(c.CrossingFraction(), 0.25) << "side " << side << ": " << c.crossing << " of "
                                          << c.reaching;
  }
}

TEST_F(VerticalCrossingsTest, DoorFramesCrossALineOfTheWallTakenForTheJunction) {
  // The wall's horizontal line 0.5 m above the floor projects where the floor junction of a wall
  // h / (h - 0.5) times as far would: the geometry that takes it for the junction.
  for (int side = 0; side < 2; ++side) {
    CorridorGeometry wrong = frame_.truth;
    const double k = pose_.height / (pose_.height - 0.5);
    if (side == 0) {
      wrong.SetWallDistances(k * wrong.LeftDistance(), wrong.RightDistance());
    } else {
      wrong.SetWallDistances(wrong.LeftDistance(), k * wrong.RightDistance());
    }
    const JunctionLine line = Extent(wrong, camera_, side, 2.0 * k, 14.0 * k);
    const VerticalCrossings c =
        CountVerticalCrossings(frame_.bgr, camera_, 1, wrong, side, line, VerticalCrossingOptions());
    EXPECT_GE(c.reaching, 2) << "side " << side;
    EXPECT_GE(c.CrossingFraction(), 0.6) << "side " << side << ": " << c.crossing << " of "
                                         << c.reaching;
  }
}

TEST(VerticalCrossings, NothingOnAnEmptyImageOrABadOption) {
  const Camera camera = Camera::FromHorizontalFov(320, 240, 1.2, 1.0);
  CorridorGeometry g;
  g.width = 2, g.camera_height = 1;
  JunctionLine line;
  line.near_end = {50, 230};
  line.far_end = {150, 130};
  const VerticalCrossings none =
      CountVerticalCrossings(cv::Mat(), camera, 1, g, 0, line, VerticalCrossingOptions());
  EXPECT_EQ(none.samples, 0);
  const cv::Mat flat(240, 320, CV_8UC3, cv::Scalar(90, 90, 90));
  const VerticalCrossings flat_count =
      CountVerticalCrossings(flat, camera, 1, g, 0, line, VerticalCrossingOptions());
  EXPECT_GT(flat_count.samples, 0);
  EXPECT_EQ(flat_count.reaching, 0);
  VerticalCrossingOptions bad;
  bad.min_run = 0;
  std::string why;
  EXPECT_FALSE(bad.Check(&why));
  EXPECT_NE(why.find("min_run"), std::string::npos);
}

}  // namespace
}  // namespace corridor
