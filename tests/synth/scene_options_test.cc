#include "synth/scene_options.h"

#include <gtest/gtest.h>

#include "synth/corridor_scene.h"
#include "synth/sequence.h"

namespace corridor {
namespace synth {
namespace {

TEST(SceneOptionsTest, DefaultsAreValidAndRangesAreChecked) {
  std::string why;
  EXPECT_TRUE(SceneOptions().Check(&why)) << why;
  SceneOptions o;
  o.width = 0.5;
  EXPECT_FALSE(o.Check(&why));
  EXPECT_NE(why.find("width"), std::string::npos) << why;
  o = SceneOptions();
  o.clutter = 1.5;
  EXPECT_FALSE(o.Check(&why));
  o = SceneOptions();
  o.noise_sigma = -1;
  EXPECT_FALSE(o.Check(&why));
}

TEST(SceneOptionsTest, ClutterPutsBoxesAgainstTheWalls) {
  SceneOptions o;
  o.clutter = 1.0;
  const CorridorScene scene = BuildScene(o);
  ASSERT_FALSE(scene.obstacles.empty());
  for (const auto& box : scene.obstacles) {
    EXPECT_GE(box.min.x(), -o.width / 2 - 1e-9);
    EXPECT_LE(box.max.x(), o.width / 2 + 1e-9);
    EXPECT_EQ(box.min.y(), 0.0);  // Standing on the floor.
  }
  o.clutter = 0;
  EXPECT_TRUE(BuildScene(o).obstacles.empty());
}

TEST(SequenceTest, DrivesForwardWithSmallPoseChanges) {
  SequenceOptions s;
  s.frames = 10;
  s.base.distance = 3.0;
  const auto poses = MakeSequence(s);
  ASSERT_EQ(poses.size(), 10u);
  EXPECT_DOUBLE_EQ(poses[0].distance, 3.0);
  EXPECT_DOUBLE_EQ(poses[9].distance, 3.0 + 9 * s.step);
  for (const auto& p : poses) {
    EXPECT_LE(std::abs(p.yaw - s.base.yaw), s.yaw_amplitude + 1e-12);
    EXPECT_LE(std::abs(p.offset - s.base.offset), s.offset_amplitude + 1e-12);
  }
}

}  // namespace
}  // namespace synth
}  // namespace corridor
