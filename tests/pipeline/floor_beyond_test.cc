// The floor beyond a junction (pipeline/floor_beyond_junction.h): a box's front foot, whose line
// runs on across the floor beyond the box, is told from a wall's foot. Truth from the generator:
// the lines are the true feet of the ray-cast scene's walls and box, projected with the true pose.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/corridor_frame.h"
#include "corridor_depth/recover_depth.h"
#include "perception/working_image.h"
#include "pipeline/floor_beyond_junction.h"
#include "synth/corridor_renderer.h"
#include "synth/corridor_scene.h"
#include "synth/real_buildings.h"
#include "tests/support/plain_corridor.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

using testing_util::FloorLine;
using testing_util::PlainCorridorCamera;
using testing_util::PlainCorridorOptions;
using testing_util::PlainScene;

constexpr double kBoxDepth = 0.55;            // How far the box stands out from the left wall, m.
constexpr double kBoxZ0 = 2.0, kBoxZ1 = 3.6;  // Its extent along the corridor, m ahead.

struct BoxFrame {
  synth::Frame frame;
  Camera camera;
  synth::CameraPose pose;
};

// A plain corridor (no doors, no clutter) with one box against the left wall, ahead of the
// camera.
BoxFrame RenderBoxFrame() {
  BoxFrame out;
  out.camera = PlainCorridorCamera();
  const synth::SceneOptions options = PlainCorridorOptions();
  synth::CorridorScene scene = PlainScene(options);
  out.pose = synth::CameraPose{0.05, 0.04, 0.1, 0.66, 3.0};
  synth::Obstacle box;
  box.kind = synth::Obstacle::kFurniture;
  box.min = Eigen::Vector3d(-0.5 * options.width, 0, out.pose.distance + kBoxZ0);
  box.max = Eigen::Vector3d(-0.5 * options.width + kBoxDepth, 1.1, out.pose.distance + kBoxZ1);
  box.color = cv::Vec3f(0.55f, 0.35f, 0.25f);
  scene.obstacles.push_back(box);
  EXPECT_TRUE(synth::RenderFrame(scene, out.camera, out.pose, &out.frame).ok());
  return out;
}

TEST(FloorBeyondTest, TheFloorGoesOnAcrossABoxFootButNotAcrossAWallFoot) {
  const BoxFrame f = RenderBoxFrame();
  ASSERT_FALSE(f.frame.bgr.empty());
  const CorridorGeometry& g = f.frame.truth;
  const WorkingImage search = HalveToWidth(f.frame.bgr, f.camera, 320);
  const double dl = g.LeftDistance(), dr = g.RightDistance();
  const JunctionLine right = FloorLine(f.camera, g, dr, 1.2, 20);
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const Vec3<double> axis = r.Axis();
  const Eigen::Vector2d vp = f.camera.Project({axis.x, axis.y, axis.z});

  // The box's front foot, seen from the box's near end to its far end.
  const JunctionLine box_foot = FloorLine(f.camera, g, -dl + kBoxDepth, kBoxZ0, kBoxZ1);
  const FloorBeyond box = MeasureFloorBeyond(search, g, box_foot, right, vp);
  ASSERT_GE(box.samples, 20);
  EXPECT_GT(box.floor_across, 0.3);

  // The left wall's foot, hidden by the box over its length and seen before and beyond it.
  const JunctionLine left_foot = FloorLine(f.camera, g, -dl, 1.2, 20);
  const FloorBeyond left = MeasureFloorBeyond(search, g, left_foot, right, vp);
  ASSERT_GE(left.samples, 20);
  EXPECT_LT(left.floor_across, 0.05);

  // The right wall's foot, seen all along.
  const FloorBeyond right_beyond =
      MeasureFloorBeyond(search, g, right, left_foot, vp);
  ASSERT_GE(right_beyond.samples, 20);
  EXPECT_LT(right_beyond.floor_across, 0.05);
}

// A short corridor: beyond its end wall's foot the line runs up the end wall, and so does the
// floor's middle at the same row, which would read as floor on both sides; the end wall's
// distance bounds what is examined.
TEST(FloorBeyondTest, TheEndWallIsNotTheFloor) {
  const Camera camera = Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180, 0.66);
  synth::SceneOptions options;
  options.width = 2.4;
  options.ceiling_height = 2.7;
  options.length = 9.0;
  options.clutter = 0;
  options.seed = 5;
  synth::CorridorScene scene = PlainScene(options);
  synth::Frame frame;
  const synth::CameraPose pose{0.04, 0.03, 0.1, 0.66, 2.0};
  ASSERT_TRUE(synth::RenderFrame(scene, camera, pose, &frame).ok());
  CorridorGeometry g = frame.truth;
  const double end = options.length - pose.distance;
  const WorkingImage search = HalveToWidth(frame.bgr, camera, 320);
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const Vec3<double> axis = r.Axis();
  const Eigen::Vector2d vp = camera.Project({axis.x, axis.y, axis.z});
  // Support up to the end wall; the lines themselves run on to the vanishing point.
  const JunctionLine left = FloorLine(camera, g, -g.LeftDistance(), 1.2, end);
  const JunctionLine right = FloorLine(camera, g, g.RightDistance(), 1.2, 50);
  g.end_distance = end;
  const FloorBeyond known = MeasureFloorBeyond(search, g, left, right, vp);
  ASSERT_GE(known.samples, 20);
  EXPECT_LT(known.floor_across, 0.05);
  g.end_distance = 0;
  const FloorBeyond unknown = MeasureFloorBeyond(search, g, left, right, vp);
  EXPECT_GT(unknown.samples, known.samples);
  EXPECT_GT(unknown.floor_across, 0.08);
}

using testing_util::ExpectOffThenRefused;
using testing_util::PresetFrame;
using testing_util::RenderPreset;

// Frames whose layout puts a wall on an object's front (a locker's, a bench's, a pillar's): the
// layout's width is far off, and the frame is refused for the floor that goes on across that
// junction (no confidence threshold: the same geometry, reported ok).
TEST(FloorBeyondTest, AnObjectsFrontTakenForTheWallIsRefused) {
  struct Case {
    const char* name;
    int scene, index, side;
  };
  for (const Case& c : {Case{"furniture", 4, 17, 1}, Case{"furniture", 9, 3, 0}}) {
    const PresetFrame f = RenderPreset(c.name, c.scene, c.index);
    const std::string label =
        std::string(c.name) + " " + std::to_string(c.scene) + " " + std::to_string(c.index);
    ASSERT_FALSE(f.frame.bgr.empty()) << label;
    const RecoverDepthResult result =
        ExpectOffThenRefused(f, 0.10, "the floor goes on across", label);
    EXPECT_GT(result.evidence.floor_across[c.side], 0.35) << label;
  }
}

// A door leaf of about the floor's colour on the near wall is not the floor: the floor's middle
// at the same depth differs from it enough. The frame stays ok and right.
TEST(FloorBeyondTest, AFloorColouredDoorIsNotTheFloor) {
  const PresetFrame f = RenderPreset("wainscot", 4, 6);
  ASSERT_FALSE(f.frame.bgr.empty());
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &result).ok());
  EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03);
}

TEST(FloorBeyondTest, NothingIsMeasuredWithoutAnImage) {
  JunctionLine a, b;
  a.far_end = Eigen::Vector2d(100, 100);
  b.far_end = Eigen::Vector2d(200, 100);
  const FloorBeyond none = MeasureFloorBeyond(WorkingImage(), CorridorGeometry(), a, b, Eigen::Vector2d(150, 50));
  EXPECT_EQ(none.samples, 0);
}

}  // namespace
}  // namespace corridor
