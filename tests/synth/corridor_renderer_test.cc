// The generator's ground truth against depths computed by hand from docs/geometry.md, section 3.
#include "synth/corridor_renderer.h"

#include <cmath>

#include <gtest/gtest.h>

namespace corridor {
namespace synth {
namespace {

Camera TestCamera() {
  Camera c;
  c.image_width = 200;
  c.image_height = 150;
  c.fx = c.fy = 120;
  c.cx = 99.5;
  c.cy = 74.5;
  c.mount_height = 0.66;
  return c;
}

SceneOptions PlainBox() {
  SceneOptions o;
  o.width = 2.4;
  o.ceiling_height = 2.7;
  o.length = 60;
  o.clutter = 0;
  o.door_density = 0;
  o.lights = false;
  return o;
}

// docs/geometry.md by hand: n = (0, cos t, sin t), m = (cos p, sin t sin p, -cos t sin p).
struct HandModel {
  double t, p, h, d_left, d_right;
  double NDotR(double /*x*/, double y) const { return std::cos(t) * y + std::sin(t); }
  double MDotR(double x, double y) const {
    return std::cos(p) * x + std::sin(t) * std::sin(p) * y - std::cos(t) * std::sin(p);
  }
};

const CameraPose kPoses[] = {{0.0, 0.0, 0.0, 0.66, 3.0},
                             {0.08, 0.12, 0.3, 0.62, 5.0},
                             {-0.03, -0.15, -0.4, 1.1, 2.0}};

TEST(CorridorRendererTest, FloorAndWallDepthsMatchHandFormulas) {
  const Camera camera = TestCamera();
  const SceneOptions options = PlainBox();
  for (const CameraPose& pose : kPoses) {
    Frame frame;
    ASSERT_TRUE(RenderFrame(options, camera, pose, &frame).ok());
    const HandModel m{pose.pitch, pose.yaw, pose.height, options.width / 2 + pose.offset,
                      options.width / 2 - pose.offset};
    int floor_checked = 0, wall_checked = 0;
    for (int v = 0; v < camera.image_height; v += 3) {
      for (int u = 0; u < camera.image_width; u += 3) {
        const double x = (u - camera.cx) / camera.fx, y = (v - camera.cy) / camera.fy;
        const double nr = m.NDotR(x, y), mr = m.MDotR(x, y);
        const double floor = nr > 0 ? m.h / nr : INFINITY;
        const double wall = mr < 0 ? -m.d_left / mr : (mr > 0 ? m.d_right / mr : INFINITY);
        const double ceiling = nr < 0 ? (m.h - options.ceiling_height) / nr : INFINITY;
        const float got = frame.depth.at<float>(v, u);
        if (floor < wall && floor < ceiling && floor < 40) {
          EXPECT_NEAR(got, floor, 1e-4 * floor) << u << "," << v;
          ++floor_checked;
        } else if (wall < floor && wall < ceiling && wall < 40) {
          EXPECT_NEAR(got, wall, 1e-4 * wall) << u << "," << v;
          ++wall_checked;
        }
      }
    }
    EXPECT_GT(floor_checked, 200);
    EXPECT_GT(wall_checked, 200);
    EXPECT_EQ(frame.truth.width, options.width);
    EXPECT_EQ(frame.truth.yaw, pose.yaw);
    EXPECT_EQ(frame.truth.camera_height, pose.height);
  }
}

TEST(CorridorRendererTest, EndWallDepthStraightAhead) {
  const Camera camera = TestCamera();
  SceneOptions options = PlainBox();
  options.length = 12;
  Frame frame;
  ASSERT_TRUE(RenderFrame(options, camera, {0, 0, 0, 1.2, 2.0}, &frame).ok());
  // The principal ray of a level camera meets the end wall 12 - 2 = 10 m ahead.
  EXPECT_NEAR(frame.depth.at<float>(74, 99), 10.0, 1e-3);
}

TEST(CorridorRendererTest, DoorRecessIsDeeperThanTheWall) {
  const Camera camera = TestCamera();
  CorridorScene scene = BuildScene(PlainBox());
  Door door;
  door.side = -1;
  door.z0 = 6.0;
  door.z1 = 9.0;
  door.height = 2.0;
  door.recess = 0.25;
  door.leaf_color = door.frame_color = cv::Vec3f(0.2f, 0.2f, 0.2f);
  scene.doors = {door};
  const CameraPose pose{0.0, 0.0, 0.0, 0.66, 1.0};  // Level, centred, 1 m into the corridor.
  Frame frame;
  ASSERT_TRUE(RenderFrame(scene, camera, pose, &frame).ok());
  // By hand: the column whose ray crosses the left wall plane (X = -d_l) 5.3 m ahead, i.e. in
  // the door opening (corridor z 6.3); the ray then meets the leaf plane X = -(d_l + r) at depth
  // (d_l + r) / |x_ray|: deeper than the wall by r / |x_ray|.
  const double d_left = 1.2;
  const int u = static_cast<int>(std::lround(camera.fx * -d_left / 5.3 + camera.cx));
  const double ray_x = (u - camera.cx) / camera.fx;
  const double wall_depth = -d_left / ray_x, leaf_depth = -(d_left + door.recess) / ray_x;
  ASSERT_GT(wall_depth + 1.0, door.z0);
  ASSERT_LT(leaf_depth + 1.0, door.z1);
  // The row that sees the leaf 1 m above the floor.
  const int v = static_cast<int>(std::lround(camera.fy * (0.66 - 1.0) / leaf_depth + camera.cy));
  EXPECT_NEAR(frame.depth.at<float>(v, u), leaf_depth, 1e-3);
  EXPECT_NEAR(leaf_depth - wall_depth, door.recess / std::abs(ray_x), 1e-9);
  // Beside the door (a column whose ray crosses the wall at corridor z 4.5, before the door),
  // the depth is the wall's.
  const int u_wall = static_cast<int>(std::lround(camera.fx * -d_left / 3.5 + camera.cx));
  EXPECT_NEAR(frame.depth.at<float>(v, u_wall), -d_left / ((u_wall - camera.cx) / camera.fx), 1e-3);
}

// truth.yaml's geometry says where the junctions are: just inside the projected junction the
// pixel is floor (floor depth, floor colour), just outside it is wall.
TEST(CorridorRendererTest, TruthAgreesWithTheJunctionsInTheImage) {
  const Camera camera = TestCamera();
  SceneOptions options = PlainBox();
  options.noise_sigma = 0;
  options.blur_sigma = 0;
  options.baseboard_height = 0;
  const CameraPose pose{0.06, 0.1, 0.25, 0.66, 2.0};
  Frame frame;
  ASSERT_TRUE(RenderFrame(options, camera, pose, &frame).ok());
  const CorridorGeometry& g = frame.truth;
  const HandModel m{g.pitch, g.yaw, g.camera_height, g.width / 2 + g.offset, g.width / 2 - g.offset};
  int checked = 0;
  for (int side = -1; side <= 1; side += 2) {
    const double x_wall = side < 0 ? -m.d_left : m.d_right;
    for (double z : {3.0, 5.0, 8.0}) {
      // P_C = R_x(t) R_y(p) (X, h, Z), by hand.
      const double x1 = std::cos(m.p) * x_wall + std::sin(m.p) * z;
      const double z1 = -std::sin(m.p) * x_wall + std::cos(m.p) * z;
      const double yc = std::cos(m.t) * m.h - std::sin(m.t) * z1;
      const double zc = std::sin(m.t) * m.h + std::cos(m.t) * z1;
      const double u = camera.fx * x1 / zc + camera.cx, v = camera.fy * yc / zc + camera.cy;
      if (u < 3 || u > camera.image_width - 4 || v < 3 || v > camera.image_height - 4) continue;
      const int inside_u = static_cast<int>(std::lround(u - 3 * side));   // Toward the floor.
      const int outside_u = static_cast<int>(std::lround(u + 3 * side));  // Toward the wall.
      const int row = static_cast<int>(std::lround(v));
      const double x_in = (inside_u - camera.cx) / camera.fx, y_in = (row - camera.cy) / camera.fy;
      EXPECT_NEAR(frame.depth.at<float>(row, inside_u), m.h / m.NDotR(x_in, y_in), 1e-3 * zc);
      const cv::Vec3b floor_color = frame.bgr.at<cv::Vec3b>(row, inside_u);
      const cv::Vec3b wall_color = frame.bgr.at<cv::Vec3b>(row, outside_u);
      EXPECT_GT(cv::norm(cv::Vec3i(floor_color) - cv::Vec3i(wall_color)), 20.0);
      ++checked;
    }
  }
  EXPECT_GE(checked, 4);
}

TEST(CorridorRendererTest, DeterministicForASeed) {
  const Camera camera = TestCamera();
  SceneOptions options = PlainBox();
  options.clutter = 0.5;
  options.door_density = 0.8;
  Frame a, b, c;
  ASSERT_TRUE(RenderFrame(options, camera, kPoses[1], &a).ok());
  ASSERT_TRUE(RenderFrame(options, camera, kPoses[1], &b).ok());
  options.seed = 2;
  ASSERT_TRUE(RenderFrame(options, camera, kPoses[1], &c).ok());
  EXPECT_EQ(cv::norm(a.bgr, b.bgr, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.depth, b.depth, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.bgr, c.bgr, cv::NORM_L1), 0.0);
}

TEST(CorridorRendererTest, RejectsPosesOutsideTheCorridor) {
  Frame frame;
  const Status status = RenderFrame(PlainBox(), TestCamera(), {0, 0, 1.19, 0.66, 2}, &frame);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("offset"), std::string::npos) << status.message();
  EXPECT_FALSE(RenderFrame(PlainBox(), TestCamera(), {0, 0, 0, 3.0, 2}, &frame).ok());
  EXPECT_FALSE(RenderFrame(PlainBox(), TestCamera(), {0, 0, 0, 0.66, 70}, &frame).ok());
  Camera bad = TestCamera();
  bad.fx = 0;
  EXPECT_FALSE(RenderFrame(PlainBox(), bad, kPoses[0], &frame).ok());
}

}  // namespace
}  // namespace synth
}  // namespace corridor
