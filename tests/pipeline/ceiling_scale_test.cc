// Scaling both walls to the trusted ceiling in a sequence (RecoverDepthOptions::max_ceiling_change):
// when this frame's ceiling, its two sides agreeing, and its width are both off the previous
// frame's by the same factor, both walls may be wrong by it; only a frame in doubt is scaled, a
// frame whose own evidence is strong keeps its walls (the recent frames may be the ones wrong
// alike). A rendered corridor, seen right and confident, against a previous geometry 1.4 times as
// large keeps its own walls, alone and in a stream; the scaling itself (by the factor of the
// heights above the camera, computed here by hand) is checked on a doubted frame by hand. A
// narrower corridor under the same ceiling, a higher ceiling over the same width, or walls and
// ceiling both farther than the trusted ones, are left alone.
#include <cmath>

#include <gtest/gtest.h>

#include "pipeline/frame_pipeline.h"
#include "pipeline/sequence_holds.h"
#include "corridor_depth/recover_depth.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

struct Seen {
  Camera camera;
  synth::Frame frame;
};

Seen PlainCorridor() {
  Seen s;
  s.camera = synth::PaperCamera(0.66);
  s.frame = testing_util::RenderCorridorFrame(s.camera, 2.4, 2.7, 3,
                                              synth::CameraPose{0.05, 0.04, 0.25, 0.66, 3.0}, 0.0);
  return s;
}

RecoverDepthResult RecoverAfter(const Seen& s, const CorridorGeometry* previous,
                                const RecoverDepthOptions& options = RecoverDepthOptions()) {
  std::unique_ptr<DepthRecoverer> recoverer;
  EXPECT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
  RecoverDepthResult result;
  EXPECT_TRUE(recoverer->Detect(s.frame.bgr, s.camera, &result).ok());
  EXPECT_TRUE(recoverer->Reconstruct(s.camera, &result, previous).ok())
      << result.status.ToString();
  return result;
}

TEST(CeilingScaleTest, AConfidentFrameKeepsItsWallsAgainstATrustedCeiling) {
  const Seen s = PlainCorridor();
  ASSERT_FALSE(s.frame.bgr.empty());
  const CorridorGeometry& truth = s.frame.truth;
  const double h = truth.camera_height, factor = 1.4;
  // Alone the frame is right and confident, its two ceiling sides agreeing: the premise.
  const RecoverDepthResult alone = RecoverAfter(s, nullptr);
  ASSERT_NEAR(alone.geometry.width, truth.width, 0.02 * truth.width);
  ASSERT_TRUE(alone.ceiling_trusted);
  ASSERT_GE(alone.confidence, RecoverDepthOptions().min_confidence);
  CorridorGeometry larger = alone.geometry;
  larger.SetWallDistances(factor * alone.geometry.LeftDistance(),
                          factor * alone.geometry.RightDistance());
  larger.ceiling_height = h + factor * (alone.geometry.ceiling_height - h);
  // The premise of the scaling holds: ceiling and width both off by the factor.
  ASSERT_NEAR(WallScaleFactor(larger, 0.25, alone.geometry, alone), factor, 0.03 * factor);

  const RecoverDepthResult kept = RecoverAfter(s, &larger);
  EXPECT_NE(kept.fallback.find("walls not scaled"), std::string::npos) << kept.fallback;
  EXPECT_FALSE(kept.walls_scaled);
  EXPECT_NEAR(kept.geometry.width, truth.width, 0.02 * truth.width);
  EXPECT_NEAR(kept.geometry.LeftDistance(), truth.LeftDistance(), 0.02 * truth.width);
}

TEST(CeilingScaleTest, ANarrowerCorridorOrAHigherCeilingAloneIsLeftAlone) {
  const Seen s = PlainCorridor();
  ASSERT_FALSE(s.frame.bgr.empty());
  const CorridorGeometry& truth = s.frame.truth;
  const RecoverDepthResult alone = RecoverAfter(s, nullptr);
  ASSERT_TRUE(alone.ceiling_trusted);
  const double h = truth.camera_height;
  // The previous frame 1.4 times as wide under the same ceiling (the corridor has narrowed).
  CorridorGeometry wider = alone.geometry;
  wider.SetWallDistances(1.4 * alone.geometry.LeftDistance(), 1.4 * alone.geometry.RightDistance());
  // The previous frame as wide, under a ceiling 1.4 times as high above the camera.
  CorridorGeometry higher = alone.geometry;
  higher.ceiling_height = h + 1.4 * (alone.geometry.ceiling_height - h);
  for (const CorridorGeometry* previous : {&wider, &higher}) {
    const RecoverDepthResult result = RecoverAfter(s, previous);
    EXPECT_EQ(result.fallback.find("both walls scaled"), std::string::npos) << result.fallback;
    EXPECT_NEAR(result.geometry.width, truth.width, 0.02 * truth.width) << result.fallback;
  }
}

// A stream whose first frame is a corridor 1.4 times as large (wider, its ceiling 1.4 times as high
// above the camera), then five frames of the plain one: each looks like both walls put 1.4 times
// too near, but each is confident on its own evidence, so none is scaled and each keeps its own
// width.
TEST(CeilingScaleTest, AStreamDoesNotScaleConfidentFrames) {
  const Seen s = PlainCorridor();
  ASSERT_FALSE(s.frame.bgr.empty());
  const double h = 0.66, factor = 1.4;
  const synth::Frame large = testing_util::RenderCorridorFrame(
      s.camera, factor * 2.4, h + factor * (2.7 - h), 3,
      synth::CameraPose{0.05, 0.04, factor * 0.25, 0.66, 3.0}, 0.0);
  ASSERT_FALSE(large.bgr.empty());
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  int next = 0;
  std::vector<bool> scaled;
  std::vector<double> widths;
  FramePipeline pipeline(*recoverer);
  ASSERT_EQ(pipeline.Run(
                [&](PipelineFrame* frame) {
                  if (next == 6) return false;
                  frame->name = std::to_string(next);
                  frame->camera = &s.camera;
                  frame->image = next == 0 ? large.bgr : s.frame.bgr;
                  ++next;
                  return true;
                },
                [&](PipelineFrame&& frame) {
                  EXPECT_TRUE(frame.result.status.ok()) << frame.result.status.ToString();
                  scaled.push_back(frame.result.walls_scaled);
                  widths.push_back(frame.result.geometry.width);
                  return true;
                }),
            6);
  // The premise: the large corridor's frame is recovered right.
  ASSERT_NEAR(widths[0], large.truth.width, 0.02 * large.truth.width);
  EXPECT_EQ(scaled, std::vector<bool>(6, false));
  for (int i = 1; i <= 5; ++i) {
    EXPECT_NEAR(widths[i], s.frame.truth.width, 0.02 * s.frame.truth.width) << i;
  }
}

// ScaleWallsToCeiling alone, by hand: the trusted ceiling 2.0 m above a camera 0.5 m high, the
// recent width 2.0 m. A frame with walls at 0.6 and 0.8 m under a ceiling 1.4 m above the camera
// (both 0.7 times the trusted) is scaled out by 2.0 / 1.4: walls 0.857 and 1.143 m. Its mirror,
// walls at 1.2 and 1.6 m under 2.8 m (both 1.4 times), would be scaled in: lines inside the floor
// never put walls too far, so it is left alone. So is a frame not in doubt, whatever its junction
// lines.
TEST(CeilingScaleTest, WallsAreScaledOutOnly) {
  CorridorGeometry previous;
  previous.camera_height = 0.5;
  previous.ceiling_height = 2.5;
  previous.SetWallDistances(1.0, 1.0);
  const auto scale = [&](double left, double right, double ceiling, CorridorGeometry* g,
                         double line = 0.5, bool doubted = false) {
    g->camera_height = 0.5;
    g->ceiling_height = ceiling;
    g->SetWallDistances(left, right);
    RecoverDepthResult result;
    result.ceiling_trusted = true;
    result.junctions.left.confidence = 0.3;
    result.junctions.right.confidence = line;
    ScaleWallsToCeiling(previous, 0.25, doubted, g, &result);
    return result.walls_scaled;
  };
  CorridorGeometry nearer;
  ASSERT_TRUE(scale(0.6, 0.8, 1.9, &nearer, 0.5, true));
  EXPECT_NEAR(nearer.LeftDistance(), 0.6 * 2.0 / 1.4, 1e-12);
  EXPECT_NEAR(nearer.RightDistance(), 0.8 * 2.0 / 1.4, 1e-12);
  EXPECT_DOUBLE_EQ(nearer.ceiling_height, 2.5);
  CorridorGeometry farther;
  EXPECT_FALSE(scale(1.2, 1.6, 3.3, &farther, 0.5, true));
  EXPECT_DOUBLE_EQ(farther.LeftDistance(), 1.2);
  EXPECT_DOUBLE_EQ(farther.RightDistance(), 1.6);
  EXPECT_DOUBLE_EQ(farther.ceiling_height, 3.3);
  EXPECT_DOUBLE_EQ(WallScaleFactor(previous, 0.25, farther, RecoverDepthResult()), 0.0);
  // A frame not in doubt keeps its walls, with weak junction lines (0.3 and 0.5) as with a strong
  // one (0.8); a doubted frame with a strong line is scaled.
  for (const double line : {0.5, 0.8}) {
    CorridorGeometry confident;
    EXPECT_FALSE(scale(0.6, 0.8, 1.9, &confident, line)) << line;
    EXPECT_DOUBLE_EQ(confident.width, 1.4) << line;
  }
  CorridorGeometry strong;
  EXPECT_TRUE(scale(0.6, 0.8, 1.9, &strong, 0.8, true));
  EXPECT_NEAR(strong.width, 2.0, 1e-12);
}

TEST(CeilingScaleTest, OptionOutsideItsRangeIsRejected) {
  for (const double bad : {-0.1, 1.0, std::nan("")}) {
    RecoverDepthOptions options;
    options.max_ceiling_change = bad;
    std::string why;
    EXPECT_FALSE(options.Check(&why)) << bad;
    EXPECT_NE(why.find("max_ceiling_change"), std::string::npos) << why;
  }
}

}  // namespace
}  // namespace corridor
