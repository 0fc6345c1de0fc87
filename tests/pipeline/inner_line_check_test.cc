// The inner-line check (pipeline/inner_line_check.h): a wall put too near (a line inside the
// floor taken for its junction) is moved out to where its ceiling junction meets the other
// side's ceiling; a wall on its junction is not. Truth from the generator: its frames and their
// true geometry.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "pipeline/inner_line_check.h"
#include "corridor_depth/recover_depth.h"
#include "corridor_depth/visualization.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"
#include "tests/support/demo_corridor.h"

namespace corridor {
namespace {

// A plain corridor with its ceiling junctions in view.
synth::Frame PlainFrame(const Camera& camera) {
  return testing_util::RenderCorridorFrame(camera, 2.4, 2.7, 3,
                                           synth::CameraPose{0.05, 0.04, 0.25, 0.66, 3.0}, 0.0);
}

// The true geometry with one wall's distance scaled down, as a line inside the floor gives it:
// the check moves that wall (and only it) back out to the truth.
TEST(InnerLineCheckTest, AWallPutTooNearIsMovedBackOut) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = PlainFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;
  for (const int side : {0, 1}) {
    for (const double shrink : {0.5, 0.75}) {
      CorridorGeometry g = testing_util::WithWallScaled(truth, side, shrink);
      const InnerLineCheck check =
          CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), InnerLineCheckOptions(), &g);
      ASSERT_TRUE(check.moved) << side << " " << shrink;
      EXPECT_EQ(check.side, side);
      EXPECT_NEAR(check.factor, 1 / shrink, 0.05 / shrink);
      EXPECT_NEAR(g.width, truth.width, 0.03 * truth.width) << side << " " << shrink;
      EXPECT_NEAR(g.offset, truth.offset, 0.05) << side << " " << shrink;
      EXPECT_EQ(g.yaw, truth.yaw);
      EXPECT_EQ(g.pitch, truth.pitch);
    }
  }
}

// A junction at a baseboard-and-reflection band's middle (JunctionPair::at_reflected_band) is not
// moved out: its own edge is faint, and the line out there is the baseboard's top. The same walls
// as above, the flag on the side put too near: nothing moves; on the other side only: it does.
TEST(InnerLineCheckTest, AJunctionAtAReflectedBandsMiddleIsNotMovedOut) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = PlainFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;
  for (const int side : {0, 1}) {
    CorridorGeometry g = testing_util::WithWallScaled(truth, side, 0.75);
    std::array<bool, 2> at_band = {false, false};
    at_band[side] = true;
    CorridorGeometry kept = g;
    EXPECT_FALSE(CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(),
                                InnerLineCheckOptions(), &kept, nullptr, {false, false}, at_band)
                     .moved)
        << side;
    EXPECT_EQ(kept.width, g.width);
    std::array<bool, 2> other = {false, false};
    other[1 - side] = true;
    EXPECT_TRUE(CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(),
                               InnerLineCheckOptions(), &g, nullptr, {false, false}, other)
                    .moved)
        << side;
  }
}

// A 16:9 view (the search image of a 1280x720 camera, 80 degrees across): the ceiling junctions
// of a 3.2 m ceiling show only from a few metres on, so the trusted side's line has fewer than
// half of its samples in view. Its support is judged on the samples in view, as the ceiling
// search judges its chosen lines; the wall put too near is still moved back out.
TEST(InnerLineCheckTest, ANarrowVerticalViewStillMovesTheWall) {
  const Camera camera = Camera::FromHorizontalFov(640, 360, 80.0 * M_PI / 180, 0.66);
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, 1.6, 3.2, 3, synth::CameraPose{0.03, 0.02, 0.05, 0.66, 3.0}, 0.0);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;
  for (const int side : {0, 1}) {
    CorridorGeometry g = testing_util::WithWallScaled(truth, side, 0.5);
    // A trusted side with a lower parallel line beside it (a baseboard's top may have been
    // taken) is not trusted this weak.
    CorridorGeometry unmoved = g;
    std::array<bool, 2> has_lower = {false, false};
    has_lower[1 - side] = true;
    EXPECT_FALSE(CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(),
                                InnerLineCheckOptions(), &unmoved, nullptr, has_lower)
                     .moved);
    const InnerLineCheck check =
        CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), InnerLineCheckOptions(), &g);
    // The premise: counted over half the samples, the trusted side is below the check's 0.35.
    EXPECT_LT(check.side_support[1 - side], InnerLineCheckOptions().min_support) << side;
    ASSERT_TRUE(check.moved) << side;
    EXPECT_EQ(check.side, side);
    EXPECT_NEAR(g.width, truth.width, 0.03 * truth.width) << side;
    EXPECT_NEAR(g.offset, truth.offset, 0.05) << side;
  }
}

// The other wall put too far (a line on the wall beyond its junction taken for it): its ceiling
// comes out too high, so the true wall's side is the lower one, as a wall put too near would make
// it. Without the band test (min_band_contrast = 0) the true wall's floor junction follows edges
// nearly all along (a box's edge or a floor line covers only part of the way): it is not moved
// (and without that test it would be: the premise, checked with max_line_support = 1). With it,
// both bands the moves would cross are wall, not floor: the far wall is moved back in.
TEST(InnerLineCheckTest, AWallOnItsJunctionIsNotMovedWhenTheOtherIsTooFar) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = PlainFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;
  InnerLineCheckOptions no_band;
  no_band.min_band_contrast = 0;
  for (const int far_side : {0, 1}) {
    double distance[2] = {truth.LeftDistance(), truth.RightDistance()};
    distance[far_side] *= 1.4;
    CorridorGeometry wrong = truth;
    wrong.SetWallDistances(distance[0], distance[1]);
    InnerLineCheckOptions always = no_band;
    always.max_line_support = 1;
    CorridorGeometry g = wrong;
    const InnerLineCheck premise =
        CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), always, &g);
    ASSERT_TRUE(premise.moved) << far_side;
    EXPECT_EQ(premise.side, 1 - far_side);
    g = wrong;
    const InnerLineCheck check =
        CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), no_band, &g);
    EXPECT_FALSE(check.moved) << far_side;
    EXPECT_GE(check.line_support, InnerLineCheckOptions().max_line_support) << far_side;
    EXPECT_EQ(g.width, wrong.width);
    g = wrong;
    const InnerLineCheck band =
        CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), InnerLineCheckOptions(), &g);
    ASSERT_TRUE(band.moved) << far_side;
    EXPECT_TRUE(band.baseboard);
    EXPECT_EQ(band.side, far_side);
    EXPECT_NEAR(g.width, truth.width, 0.03 * truth.width) << far_side;
  }
}

// A baseboard's top taken for one junction: that wall is put too far by h / (h - b) (b the
// generator's baseboard height, h the camera's), its ceiling too high by as much. The band between
// the taken line and the junction below it is baseboard, as is the band above the other wall's
// junction: the far wall is moved in, to the truth, and the note says so. Without the band test
// (min_band_contrast = 0) the check would move the true wall out instead (the premise).
TEST(InnerLineCheckTest, ABaseboardTopTakenForAJunctionMovesThatWallIn) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = PlainFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;
  const double b = synth::SceneOptions().baseboard_height;
  ASSERT_GT(b, 0.05);
  const double too_far = truth.camera_height / (truth.camera_height - b);
  for (const int far_side : {0, 1}) {
    double distance[2] = {truth.LeftDistance(), truth.RightDistance()};
    distance[far_side] *= too_far;
    CorridorGeometry wrong = truth;
    wrong.SetWallDistances(distance[0], distance[1]);
    InnerLineCheckOptions no_band;
    no_band.min_band_contrast = 0;
    CorridorGeometry g = wrong;
    const InnerLineCheck premise =
        CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), no_band, &g);
    EXPECT_TRUE(!premise.moved || premise.side == 1 - far_side) << far_side;
    g = wrong;
    const InnerLineCheck check =
        CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), InnerLineCheckOptions(), &g);
    ASSERT_TRUE(check.moved) << far_side;
    EXPECT_TRUE(check.baseboard);
    EXPECT_EQ(check.side, far_side);
    EXPECT_NEAR(check.factor, 1 / too_far, 0.04);
    EXPECT_GT(check.band_contrast[0], InnerLineCheckOptions().min_band_contrast);
    EXPECT_GT(check.band_contrast[1], InnerLineCheckOptions().min_band_contrast);
    EXPECT_NEAR(g.width, truth.width, 0.03 * truth.width) << far_side;
    EXPECT_NEAR(g.offset, truth.offset, 0.05) << far_side;
    EXPECT_EQ(g.yaw, truth.yaw);
    EXPECT_EQ(g.pitch, truth.pitch);
    const std::string note = DescribeInnerLineCheck(check);
    EXPECT_NE(note.find(std::string(far_side == 0 ? "left" : "right") + " wall moved in"),
              std::string::npos)
        << note;
  }
}

// The generated demo corridor's frame 4 (corridor_synth --preset=sequence --seed=7): its right
// junction's line is a baseboard's top, and the inner-line check once moved the true left wall out
// to match, both walls then 18% too far. The width follows the truth: the junction search finds
// the baseboard's foot below that line itself (lower_edge.h).
TEST(InnerLineCheckTest, TheDemoCorridorsBaseboardFrameHasItsWidth) {
  const synth::ScenePreset preset = testing_util::DemoCorridor();
  synth::Frame frame;
  ASSERT_TRUE(synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera,
                                 preset.poses.at(4), &frame)
                  .ok());
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, RecoverDepthOptions(), &result).ok());
  EXPECT_NEAR(result.geometry.width, frame.truth.width, 0.02 * frame.truth.width)
      << result.fallback;
  EXPECT_EQ(result.moved_side, -1) << result.fallback;
}

TEST(InnerLineCheckTest, TheTrueGeometryStays) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = PlainFrame(camera);
  CorridorGeometry g = frame.truth;
  const InnerLineCheck check =
      CheckInnerLine(frame.bgr, camera, CeilingDetectorOptions(), InnerLineCheckOptions(), &g);
  EXPECT_FALSE(check.moved);
  EXPECT_GT(check.side_support[0], 0.45);
  EXPECT_GT(check.side_support[1], 0.45);
  EXPECT_NEAR(check.side_height[0], frame.truth.ceiling_height, 0.03 * frame.truth.ceiling_height);
  EXPECT_NEAR(check.side_height[1], frame.truth.ceiling_height, 0.03 * frame.truth.ceiling_height);
  EXPECT_EQ(g.width, frame.truth.width);
}

// Frame 0 of the paper preset's Cord_H02 (its right junction a line inside the floor), recovered
// without the inner-line check and with the defaults.
struct InnerLineFrame {
  synth::ScenePreset preset;
  synth::Frame frame;
  RecoverDepthResult unchecked, checked;
};

void RecoverInnerLineFrame(InnerLineFrame* f) {
  for (const auto& p : synth::PaperPreset()) {
    if (p.name == "Cord_H02") f->preset = p;
  }
  ASSERT_EQ(f->preset.name, "Cord_H02");
  ASSERT_TRUE(synth::RenderFrame(synth::BuildScene(f->preset.scene), f->preset.camera,
                                 f->preset.poses.at(0), &f->frame)
                  .ok());
  RecoverDepthOptions off;
  off.ceiling_checks_inner_lines = false;
  ASSERT_TRUE(RecoverDepth(f->frame.bgr, f->preset.camera, off, &f->unchecked).ok());
  ASSERT_TRUE(
      RecoverDepth(f->frame.bgr, f->preset.camera, RecoverDepthOptions(), &f->checked).ok());
}

// Frame 0 of the paper preset's Cord_H02: the right junction is a line inside the floor (the
// width 24% too narrow without the check). With it, the width follows the truth and the note
// says which wall moved.
TEST(InnerLineCheckTest, ThePipelineMovesTheWallOfAnInnerLine) {
  InnerLineFrame f;
  ASSERT_NO_FATAL_FAILURE(RecoverInnerLineFrame(&f));
  EXPECT_LT(f.unchecked.geometry.width, 0.85 * f.frame.truth.width);  // The premise.
  EXPECT_NEAR(f.checked.geometry.width, f.frame.truth.width, 0.05 * f.frame.truth.width);
  EXPECT_NE(f.checked.fallback.find("right wall moved out"), std::string::npos)
      << f.checked.fallback;
  EXPECT_NEAR(f.checked.geometry.ceiling_height, f.frame.truth.ceiling_height,
              0.05 * f.frame.truth.ceiling_height);
}

// The same frame in a sequence after a frame as narrow as the unchecked one (a recent width that
// agrees better with the line inside the floor): the moved frame's own confidence is at least
// min_confidence, so the recent width does not veto the move. Asked for a confidence above the
// moved frame's, the frame is in doubt and the recent width keeps the unmoved wall.
TEST(InnerLineCheckTest, ARecentNarrowWidthDoesNotVetoAConfidentMove) {
  InnerLineFrame f;
  ASSERT_NO_FATAL_FAILURE(RecoverInnerLineFrame(&f));
  const CorridorGeometry previous = f.unchecked.geometry;
  const auto after = [&](double min_confidence) {
    RecoverDepthOptions options;
    options.min_confidence = min_confidence;
    std::unique_ptr<DepthRecoverer> recoverer;
    EXPECT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
    RecoverDepthResult result;
    EXPECT_TRUE(recoverer->Detect(f.frame.bgr, f.preset.camera, &result).ok());
    recoverer->Reconstruct(f.preset.camera, &result, &previous);
    return result;
  };
  ASSERT_GE(f.checked.confidence, RecoverDepthOptions().min_confidence);  // The premise.
  const RecoverDepthResult confident = after(RecoverDepthOptions().min_confidence);
  EXPECT_TRUE(confident.status.ok()) << confident.status.ToString();
  EXPECT_NE(confident.fallback.find("right wall moved out"), std::string::npos)
      << confident.fallback;
  EXPECT_NEAR(confident.geometry.width, f.frame.truth.width, 0.05 * f.frame.truth.width);
  const RecoverDepthResult doubted = after(std::min(1.0, f.checked.confidence + 0.05));
  EXPECT_EQ(doubted.fallback.find("right wall moved out"), std::string::npos) << doubted.fallback;
  EXPECT_LT(doubted.geometry.width, 0.85 * f.frame.truth.width);
}

// The picture of a moved wall: the geometry's own right junction (thin white) lies on the true
// one (the generator's, projected by hand), where the detected line does not; the note is a
// caption. Without the check the frame has no note and no white line there.
TEST(InnerLineCheckTest, ThePictureShowsTheMovedWall) {
  InnerLineFrame f;
  ASSERT_NO_FATAL_FAILURE(RecoverInnerLineFrame(&f));
  const Eigen::Vector3d truth = testing_util::TrueJunction(f.frame.truth, f.preset.camera, 1);
  // Pure white pixels within 2 px of the true right junction, below the captions.
  const auto white_on_truth = [&](const RecoverDepthResult& result) {
    const cv::Mat panel = MakeResultPanel(f.frame.bgr, result, 15.0);
    int count = 0;
    for (int v = 80; v < f.frame.bgr.rows; ++v) {
      for (int u = 0; u < f.frame.bgr.cols; ++u) {
        if (std::abs(truth.dot(Eigen::Vector3d(u, v, 1))) > 2.0) continue;
        count += panel.at<cv::Vec3b>(v, u) == cv::Vec3b(255, 255, 255);
      }
    }
    return count;
  };
  ASSERT_TRUE(f.unchecked.fallback.empty()) << f.unchecked.fallback;
  EXPECT_EQ(white_on_truth(f.unchecked), 0);
  EXPECT_GT(white_on_truth(f.checked), 40);
}

TEST(InnerLineCheckTest, BadOptionsAreRejected) {
  InnerLineCheckOptions options;
  std::string why;
  EXPECT_TRUE(options.Check(&why));
  options.min_disagreement = 0;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("min_disagreement"), std::string::npos) << why;
  options = InnerLineCheckOptions();
  options.min_above_camera = -1;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("min_above_camera"), std::string::npos) << why;
  options = InnerLineCheckOptions();
  options.strong_support = 0;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("strong_support"), std::string::npos) << why;
  for (const double bad : {0.0, 1.5, std::nan("")}) {
    options = InnerLineCheckOptions();
    options.max_line_support = bad;
    EXPECT_FALSE(options.Check(&why)) << bad;
    EXPECT_NE(why.find("max_line_support"), std::string::npos) << why;
  }
  RecoverDepthOptions recover;
  recover.inner_line.min_support = 2;
  EXPECT_FALSE(recover.Check(&why));
  EXPECT_NE(why.find("inner_line"), std::string::npos) << why;
}

}  // namespace
}  // namespace corridor
