// The far-wall check (pipeline/far_wall_check.h): a wall put far too far, on a line seen through a
// glass wall (the lit room's floor line behind it), has its ceiling junction only above any
// ceiling searched; the check moves it back in to the glass plane. A wall on its junction is not
// moved. Truth from the generator: its frames and their true geometry.
#include <gtest/gtest.h>

#include "perception/ceiling_detector.h"
#include "pipeline/far_wall_check.h"
#include "synth/corridor_renderer.h"
#include "synth/corridor_scene.h"
#include "synth/presets.h"

namespace corridor {
namespace {

constexpr double kRoomDepth = 3.0;  // The lit room's back wall behind the glass plane, m.

// A corridor whose right wall is glass from floor to ceiling along the whole view, a lit room
// kRoomDepth behind it.
synth::Frame GlassFrame(const Camera& camera) {
  synth::SceneOptions options;
  options.width = 1.8;
  options.ceiling_height = 2.6;
  options.clutter = 0;
  options.seed = 5;
  synth::CorridorScene scene = synth::BuildScene(options);
  synth::GlassRun glass;
  glass.side = 1;
  glass.z0 = 0;
  glass.z1 = options.length - 1;
  glass.top = options.ceiling_height;
  glass.room_depth = kRoomDepth;
  glass.frame_color = cv::Vec3f(0.2f, 0.2f, 0.2f);
  glass.room_floor_color = cv::Vec3f(0.35f, 0.4f, 0.3f);
  glass.room_wall_color = cv::Vec3f(0.6f, 0.7f, 0.5f);
  glass.desk_color = cv::Vec3f(0.2f, 0.3f, 0.4f);
  scene.glass.push_back(glass);
  synth::Frame frame;
  EXPECT_TRUE(synth::RenderFrame(scene, camera, synth::CameraPose{0.06, 0.03, 0.1, 0.66, 3.0},
                                 &frame)
                  .ok());
  return frame;
}

// The ceiling search for `g`'s walls, then the far-wall check on them.
InnerLineCheck Check(const synth::Frame& frame, const Camera& camera, CorridorGeometry* g) {
  CeilingEstimate found;
  EXPECT_TRUE(DetectCeiling(frame.bgr, camera, *g, CeilingDetectorOptions(), &found).ok());
  return CheckFarWall(frame.bgr, camera, CeilingDetectorOptions(), InnerLineCheckOptions(), found,
                      g);
}

TEST(FarWallCheckTest, AWallOnTheRoomBehindTheGlassMovesBackToTheGlass) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = GlassFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;
  CorridorGeometry g = truth;
  g.SetWallDistances(truth.LeftDistance(), truth.RightDistance() + kRoomDepth);
  const InnerLineCheck check = Check(frame, camera, &g);
  ASSERT_TRUE(check.moved);
  EXPECT_TRUE(check.far);
  EXPECT_EQ(check.side, 1);
  EXPECT_LT(check.factor, 1.0);
  EXPECT_NEAR(g.RightDistance(), truth.RightDistance(), 0.03 * truth.RightDistance());
  EXPECT_NEAR(g.LeftDistance(), truth.LeftDistance(), 1e-9);
  EXPECT_NE(DescribeInnerLineCheck(check).find("right wall moved in"), std::string::npos);
}

TEST(FarWallCheckTest, WallsOnTheirJunctionsAreNotMoved) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = GlassFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  CorridorGeometry g = frame.truth;
  EXPECT_FALSE(Check(frame, camera, &g).moved);
  EXPECT_EQ(g.width, frame.truth.width);
  EXPECT_EQ(g.offset, frame.truth.offset);
}

// Off (far_max_height no higher than the ceiling search's max_height): nothing moves.
TEST(FarWallCheckTest, OffMovesNothing) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = GlassFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  CorridorGeometry g = frame.truth;
  g.SetWallDistances(frame.truth.LeftDistance(), frame.truth.RightDistance() + kRoomDepth);
  CeilingEstimate found;
  ASSERT_TRUE(DetectCeiling(frame.bgr, camera, g, CeilingDetectorOptions(), &found).ok());
  InnerLineCheckOptions off;
  off.far_max_height = 0;
  EXPECT_FALSE(CheckFarWall(frame.bgr, camera, CeilingDetectorOptions(), off, found, &g).moved);
}

}  // namespace
}  // namespace corridor
