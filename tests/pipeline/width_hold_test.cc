// Holding the width in a sequence: on a generated frame where a box hides the right junction, the
// detector takes an edge inside the floor for it and the width comes out far too narrow. Given the
// previous frame's true geometry, the width of the frame in doubt is held, and the result follows
// the generator's truth (a confident frame keeps its own);
// a wider width, or max_width_change = 0, is left alone; so is a narrower width that the frame's
// own ceiling confirms, or that the ceiling's checks correct first.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/ceiling_agreement.h"
#include "pipeline/sequence_prior.h"
#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

struct HiddenJunction {
  Camera camera;
  synth::Frame frame;         // Frame 10 of the paper preset's Cord_E05: a box hides the
                              // right junction.
  synth::Frame before;        // Frame 9, where both junctions are seen.
  synth::Frame confirmed;     // Frame 8: both junctions seen, their ceiling sides alike.
  CorridorGeometry previous;  // The true geometry of frame 9.
};

HiddenJunction MakeHiddenJunction() {
  HiddenJunction h;
  for (const auto& preset : synth::PaperPreset()) {
    if (preset.name != "Cord_E05") continue;
    h.camera = preset.camera;
    EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera,
                                   preset.poses.at(10), &h.frame)
                    .ok());
    EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera,
                                   preset.poses.at(9), &h.before)
                    .ok());
    EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera,
                                   preset.poses.at(8), &h.confirmed)
                    .ok());
    h.previous = h.before.truth;
  }
  EXPECT_FALSE(h.frame.bgr.empty()) << "no Cord_E05 in the paper preset";
  return h;
}

// The defaults without the inner-line check, which finds this frame's right wall on its own (its
// ceiling junction): off, so that the width hold is what these tests see. And without the
// inside-floor rule, which takes a line beside the one taken here whose ceiling agrees with the
// left side's: with this line the ceiling says which wall is wrong (3.23 m on the right, 2.58 m
// on the left), so that a doubted frame keeps the left wall (HoldWidth).
RecoverDepthOptions HoldOptions() {
  RecoverDepthOptions options;
  options.ceiling_checks_inner_lines = false;
  options.perception.inside_floor_likeness = 0;
  return options;
}

// Frame 10 (or `image`) recovered with `options`, given `previous`. `doubted`: its junctions
// count as the tracker's (a frame in doubt, which a hold may overrule; this frame's own
// confidence, 0.9, does not put it in doubt).
RecoverDepthResult RecoverWith(const HiddenJunction& h, const RecoverDepthOptions& options,
                               const CorridorGeometry* previous, const cv::Mat* image = nullptr,
                               bool doubted = false) {
  std::unique_ptr<DepthRecoverer> recoverer;
  EXPECT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
  RecoverDepthResult result;
  recoverer->Detect(image != nullptr ? *image : h.frame.bgr, h.camera, &result);
  EXPECT_TRUE(result.status.ok()) << result.status.ToString();
  result.junctions_tracked = doubted;
  recoverer->Reconstruct(h.camera, &result, previous);
  EXPECT_TRUE(result.status.ok()) << result.status.ToString();
  return result;
}

TEST(WidthHoldTest, ANarrowWidthAfterAWideOneIsHeldAndFollowsTheTruth) {
  const HiddenJunction h = MakeHiddenJunction();
  const CorridorGeometry& truth = h.frame.truth;
  // Alone, the frame's width is far too narrow: the premise of this test.
  const RecoverDepthResult alone = RecoverWith(h, HoldOptions(), nullptr);
  ASSERT_LT(alone.geometry.width, 0.85 * truth.width);
  EXPECT_FALSE(alone.width_held);

  // Not in doubt, the frame keeps its own width (its ceiling's answer could be a box's face).
  const RecoverDepthResult kept = RecoverWith(h, HoldOptions(), &h.previous);
  EXPECT_FALSE(kept.width_held);
  EXPECT_TRUE(kept.width_kept);
  EXPECT_DOUBLE_EQ(kept.geometry.width, alone.geometry.width);

  const RecoverDepthResult held = RecoverWith(h, HoldOptions(), &h.previous, nullptr, true);
  EXPECT_TRUE(held.width_held);
  EXPECT_NE(held.fallback.find("recent width held"), std::string::npos) << held.fallback;
  EXPECT_DOUBLE_EQ(held.geometry.width, h.previous.width);
  // Both walls within 3% of the generator's (the left junction is the visible one).
  EXPECT_NEAR(held.geometry.LeftDistance(), truth.LeftDistance(), 0.03 * truth.LeftDistance());
  EXPECT_NEAR(held.geometry.RightDistance(), truth.RightDistance(), 0.03 * truth.RightDistance());

  RecoverDepthOptions off = HoldOptions();
  off.max_width_change = 0;
  const RecoverDepthResult not_held = RecoverWith(h, off, &h.previous, nullptr, true);
  EXPECT_FALSE(not_held.width_held);
  EXPECT_DOUBLE_EQ(not_held.geometry.width, alone.geometry.width);
}

TEST(WidthHoldTest, AWiderWidthIsNotHeld) {
  const HiddenJunction h = MakeHiddenJunction();
  CorridorGeometry narrow = h.previous;
  narrow.width = 0.5 * h.previous.width;
  const RecoverDepthResult result = RecoverWith(h, HoldOptions(), &narrow);
  EXPECT_FALSE(result.width_held);
  // (The frame's ceiling, measured against its too-near right wall, may still be held.)
  EXPECT_EQ(result.fallback.find("width"), std::string::npos) << result.fallback;
}

// The previous frame's width was the wrong one (30% too wide): this frame's narrower walls, whose
// two ceiling junctions, each searched alone, agree, are kept.
TEST(WidthHoldTest, AWidthItsOwnCeilingConfirmsIsNotHeld) {
  const HiddenJunction h = MakeHiddenJunction();
  const CorridorGeometry& truth = h.confirmed.truth;
  CorridorGeometry wrong = truth;
  wrong.width = 1.3 * truth.width;
  const RecoverDepthResult alone = RecoverWith(h, HoldOptions(), nullptr, &h.confirmed.bgr);
  // The premise: alone the frame is right, and much narrower than the wrong previous width.
  ASSERT_NEAR(alone.geometry.width, truth.width, 0.03 * truth.width);
  ASSERT_LT(alone.geometry.width, 0.85 * wrong.width);
  EXPECT_TRUE(alone.ceiling_trusted);
  const RecoverDepthResult result = RecoverWith(h, HoldOptions(), &wrong, &h.confirmed.bgr);
  EXPECT_FALSE(result.width_held) << result.fallback;
  EXPECT_DOUBLE_EQ(result.geometry.width, alone.geometry.width);
}

// The ceiling's checks come before the hold: with the inner-line check on, this frame's right
// wall is moved out to its ceiling junction's distance (within 5% here, as that check measures it),
// and nothing is left to hold.
TEST(WidthHoldTest, TheCeilingsChecksComeBeforeTheHold) {
  const HiddenJunction h = MakeHiddenJunction();
  const CorridorGeometry& truth = h.frame.truth;
  const RecoverDepthResult result = RecoverWith(h, RecoverDepthOptions(), &h.previous);
  EXPECT_FALSE(result.width_held) << result.fallback;
  EXPECT_NE(result.fallback.find("right wall moved out"), std::string::npos) << result.fallback;
  EXPECT_NEAR(result.geometry.width, truth.width, 0.05 * truth.width);
}

// The recent width may veto the inner-line check's move (it agrees better with the line the move
// would replace), but not a move after which the frame's two ceiling sides, each searched alone,
// agree: then the recent width is the wrong one. Here the recent width is this frame's own too
// narrow one (as frames whose right line was the same wrong one would give).
TEST(WidthHoldTest, AMoveItsOwnCeilingConfirmsIsNotVetoedByTheRecentWidth) {
  const HiddenJunction h = MakeHiddenJunction();
  const CorridorGeometry& truth = h.frame.truth;
  const RecoverDepthResult narrow = RecoverWith(h, HoldOptions(), nullptr);
  ASSERT_LT(narrow.geometry.width, 0.85 * truth.width);  // The premise: the right line is wrong.
  CorridorGeometry recent = h.previous;
  recent.width = narrow.geometry.width;
  const RecoverDepthResult result = RecoverWith(h, RecoverDepthOptions(), &recent);
  EXPECT_NE(result.fallback.find("right wall moved out"), std::string::npos) << result.fallback;
  EXPECT_NEAR(result.geometry.width, truth.width, 0.05 * truth.width);
  const double disagreement = CeilingDisagreement(result.ceiling, result.geometry.camera_height);
  EXPECT_GE(disagreement, 0);
  EXPECT_LE(disagreement, std::log(kCeilingSidesAgree));
}

// In a stream, the width is held at most three frames in a row: then the narrow width is let go
// (the corridor may really have narrowed). Frames 1-5 are frame 10 in doubt (its junctions count
// as the tracker's), fed in order with the sequence's prior.
TEST(WidthHoldTest, AStreamHoldsTheWidthThreeFramesAtMost) {
  const HiddenJunction h = MakeHiddenJunction();
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(HoldOptions(), &recoverer).ok());
  SequencePrior prior;
  std::vector<bool> held;
  std::vector<double> widths;
  for (int i = 0; i < 6; ++i) {
    RecoverDepthResult result;
    recoverer->Detect(i == 0 ? h.before.bgr : h.frame.bgr, h.camera, &result);
    ASSERT_TRUE(result.status.ok()) << i << ": " << result.status.ToString();
    result.junctions_tracked = i > 0;
    recoverer->Reconstruct(h.camera, &result, prior.Previous());
    EXPECT_TRUE(result.status.ok()) << i << ": " << result.status.ToString();
    prior.Update(result);
    held.push_back(result.width_held);
    widths.push_back(result.geometry.width);
  }
  EXPECT_EQ(held, (std::vector<bool>{false, true, true, true, false, false}));
  EXPECT_NEAR(widths[0], h.before.truth.width, 0.03 * h.before.truth.width);
  for (int i = 1; i <= 3; ++i) EXPECT_DOUBLE_EQ(widths[i], widths[0]) << i;
  EXPECT_LT(widths[4], 0.85 * widths[0]);
}

TEST(WidthHoldTest, OptionOutsideItsRangeIsRejected) {
  RecoverDepthOptions options;
  std::unique_ptr<DepthRecoverer> recoverer;
  for (const double bad : {-0.1, 1.0, std::nan("")}) {
    options.max_width_change = bad;
    const Status status = DepthRecoverer::Create(options, &recoverer);
    EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << bad;
    EXPECT_NE(status.message().find("max_width_change"), std::string::npos) << status.message();
  }
}

}  // namespace
}  // namespace corridor
