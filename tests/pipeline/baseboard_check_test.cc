// The ceiling as referee of the baseboard rule. On frame 0 of the paper preset's Cord_E01 the
// right junction's pair choice takes the top of the baseboard, and the width comes out 13% too
// wide; the two ceiling junctions, each searched alone, then disagree. With the lower parallel
// line they agree, and the geometry follows the generator's truth.
#include <gtest/gtest.h>

#include "pipeline/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

synth::ScenePreset Scene(const std::string& name) {
  for (const auto& preset : synth::PaperPreset()) {
    if (preset.name == name) return preset;
  }
  ADD_FAILURE() << "no " << name << " in the paper preset";
  return synth::ScenePreset();
}

synth::ScenePreset E01() { return Scene("Cord_E01"); }

// Frame `pose` of a paper-preset scene (empty when it cannot be rendered).
synth::Frame RenderPose(const synth::ScenePreset& preset, size_t pose) {
  synth::Frame frame;
  EXPECT_TRUE(
      synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera, preset.poses.at(pose), &frame)
          .ok());
  return frame;
}

TEST(BaseboardCheckTest, TheCeilingPicksTheLowerOfTwoParallelLines) {
  const synth::ScenePreset preset = E01();
  const synth::Frame frame = RenderPose(preset, 0);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;

  RecoverDepthOptions off;
  off.ceiling_checks_baseboards = false;
  RecoverDepthResult upper;
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, off, &upper).ok());
  // The premise: the upper line gives a width far too wide, and a lower line was there.
  ASSERT_GT(upper.geometry.width, 1.08 * truth.width);
  ASSERT_TRUE(upper.junctions.has_left_lower || upper.junctions.has_right_lower);
  EXPECT_TRUE(upper.fallback.empty()) << upper.fallback;

  RecoverDepthResult checked;
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, RecoverDepthOptions(), &checked).ok());
  EXPECT_NEAR(checked.geometry.width, truth.width, 0.02 * truth.width);
  EXPECT_NEAR(checked.geometry.RightDistance(), truth.RightDistance(),
              0.03 * truth.RightDistance());
  EXPECT_NEAR(checked.geometry.ceiling_height, preset.scene.ceiling_height,
              0.03 * preset.scene.ceiling_height);
  EXPECT_NE(checked.fallback.find("baseboard"), std::string::npos) << checked.fallback;
}

// Frame 3 of Cord_H01: the upper line (a baseboard's top) skews the whole geometry, so that
// neither ceiling junction is found where it is sought and the two cannot be compared at all.
// The lower line gives a ceiling whose two sides, each searched alone, agree; it is taken.
TEST(BaseboardCheckTest, ALowerLineThatMakesTheCeilingAgreeIsTakenWhenNoneWasComparable) {
  const synth::ScenePreset preset = Scene("Cord_H01");
  const synth::Frame frame = RenderPose(preset, 3);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;

  RecoverDepthOptions off;
  off.ceiling_checks_baseboards = false;
  RecoverDepthResult upper;
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, off, &upper).ok());
  // The premise: far too wide, a lower line there, and no two ceiling sides strong enough to
  // compare (the stricter check's 0.45 support).
  ASSERT_GT(upper.geometry.width, 1.08 * truth.width);
  ASSERT_TRUE(upper.junctions.has_left_lower || upper.junctions.has_right_lower);
  ASSERT_TRUE(!upper.ceiling.found || upper.ceiling.side_support[0] < 0.45 ||
              upper.ceiling.side_support[1] < 0.45);

  RecoverDepthResult checked;
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, RecoverDepthOptions(), &checked).ok());
  EXPECT_NEAR(checked.geometry.width, truth.width, 0.02 * truth.width);
  EXPECT_NEAR(checked.geometry.offset, truth.offset, 0.05);
  ASSERT_TRUE(checked.ceiling.found);
  EXPECT_NEAR(checked.ceiling.height, preset.scene.ceiling_height,
              0.03 * preset.scene.ceiling_height);
  EXPECT_NE(checked.fallback.find("baseboard"), std::string::npos) << checked.fallback;
}

// Where both ceiling junctions already agree (a frame of the same corridor with both junctions
// right), nothing changes.
TEST(BaseboardCheckTest, AgreeingCeilingJunctionsChangeNothing) {
  const synth::ScenePreset preset = E01();
  const synth::Frame frame = RenderPose(preset, 6);
  ASSERT_FALSE(frame.bgr.empty());
  RecoverDepthOptions off;
  off.ceiling_checks_baseboards = false;
  RecoverDepthResult a, b;
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, off, &a).ok());
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, RecoverDepthOptions(), &b).ok());
  EXPECT_NEAR(a.geometry.width, frame.truth.width, 0.03 * frame.truth.width);
  EXPECT_EQ(a.geometry.width, b.geometry.width);
  EXPECT_EQ(a.geometry.offset, b.geometry.offset);
  EXPECT_TRUE(b.fallback.empty()) << b.fallback;
}

}  // namespace
}  // namespace corridor
