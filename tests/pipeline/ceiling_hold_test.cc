// Holding the ceiling height in a sequence (RecoverDepthOptions::max_ceiling_disagreement): a frame
// whose own ceiling is trusted keeps it; a confident frame whose ceiling junctions are painted out
// does not take the previous frame's height; SequencePrior passes on only trusted (or held)
// heights. Ground truth is the generator's.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "corridor_depth/recover_depth.h"
#include "pipeline/sequence_prior.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

struct PaperFrame {
  Camera camera;
  synth::Frame frame;  // Frame 0 of the paper preset's Cord_E01: both ceiling junctions in view.
};

PaperFrame MakeFrame() {
  const synth::ScenePreset preset = testing_util::PaperScene("Cord_E01");
  PaperFrame p;
  p.camera = preset.camera;
  if (preset.poses.empty()) return p;
  EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera,
                                 preset.poses.at(0), &p.frame)
                  .ok());
  return p;
}

RecoverDepthResult RecoverWith(const cv::Mat& bgr, const Camera& camera,
                               const RecoverDepthOptions& options,
                               const CorridorGeometry* previous) {
  std::unique_ptr<DepthRecoverer> recoverer;
  EXPECT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
  RecoverDepthResult result;
  recoverer->Recover(bgr, camera, &result, previous);
  EXPECT_TRUE(result.status.ok()) << result.status.ToString();
  return result;
}

// The image above the horizon painted one flat grey: no ceiling junction left to find.
cv::Mat WithoutCeiling(const PaperFrame& p) {
  cv::Mat bgr = p.frame.bgr.clone();
  const int horizon = static_cast<int>(p.camera.cy - p.camera.fy * std::tan(p.frame.truth.pitch));
  bgr.rowRange(0, horizon - 10).setTo(cv::Scalar(128, 128, 128));
  return bgr;
}

TEST(CeilingHoldTest, ATrustedCeilingIsKeptWhateverThePreviousFrameSaid) {
  const PaperFrame p = MakeFrame();
  const double truth = p.frame.truth.ceiling_height;
  CorridorGeometry previous = p.frame.truth;
  previous.ceiling_height = 3.5;  // A different height: must not replace this frame's.
  const RecoverDepthResult r = RecoverWith(p.frame.bgr, p.camera, RecoverDepthOptions(), &previous);
  ASSERT_TRUE(r.ceiling_trusted) << "premise: both ceiling sides seen and agreeing";
  EXPECT_FALSE(r.ceiling_held);
  EXPECT_NEAR(r.geometry.ceiling_height, truth, 0.03 * truth);
}

// A frame whose ceiling is painted out is confident on its walls: the sequence does not give it
// the previous frame's ceiling (only a frame in doubt takes it, by hand in own_evidence_test.cc);
// it keeps none, and says so.
TEST(CeilingHoldTest, AConfidentFrameWithoutItsCeilingKeepsNone) {
  const PaperFrame p = MakeFrame();
  const cv::Mat painted = WithoutCeiling(p);
  const RecoverDepthResult alone = RecoverWith(painted, p.camera, RecoverDepthOptions(), nullptr);
  ASSERT_FALSE(alone.ceiling_trusted) << "premise: the painted frame's ceiling is not trusted";
  ASSERT_GE(alone.confidence, RecoverDepthOptions().min_confidence) << "premise: not in doubt";
  EXPECT_FALSE(alone.ceiling_held);

  const CorridorGeometry previous = p.frame.truth;  // The generator's height, 2.7 m.
  const RecoverDepthResult kept = RecoverWith(painted, p.camera, RecoverDepthOptions(), &previous);
  EXPECT_FALSE(kept.ceiling_held);
  EXPECT_TRUE(kept.ceiling_kept);
  EXPECT_EQ(kept.geometry.ceiling_height, alone.geometry.ceiling_height);
  EXPECT_NE(kept.fallback.find("previous frame's 2.70 m not held"), std::string::npos)
      << kept.fallback;

  RecoverDepthOptions off;
  off.max_ceiling_disagreement = 0;
  const RecoverDepthResult not_held = RecoverWith(painted, p.camera, off, &previous);
  EXPECT_FALSE(not_held.ceiling_held);
  EXPECT_FALSE(not_held.ceiling_kept);
  EXPECT_EQ(not_held.geometry.ceiling_height, alone.geometry.ceiling_height);
}

RecoverDepthResult Result(double ceiling_height, bool trusted, bool held) {
  RecoverDepthResult r;
  r.has_geometry = true;
  r.geometry.width = 2.0;
  r.geometry.camera_height = 0.66;
  r.geometry.ceiling_height = ceiling_height;
  r.ceiling_trusted = trusted;
  r.ceiling_held = held;
  return r;
}

TEST(CeilingHoldTest, TheSequencePassesOnOnlyTrustedOrHeldHeights) {
  SequencePrior prior;
  prior.Update(Result(3.4, false, false));  // First frame, untrusted: no ceiling to hold.
  ASSERT_NE(prior.Previous(), nullptr);
  EXPECT_EQ(prior.Previous()->ceiling_height, 0.0);
  prior.Update(Result(2.7, true, false));  // Trusted.
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.7);
  prior.Update(Result(3.6, false, false));  // Untrusted: the trusted one stays.
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.7);
  prior.Update(Result(2.7, false, true));  // Held: the same height.
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.7);
  prior.Update(Result(2.9, true, false));  // A new trusted height replaces it.
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.9);
  RecoverDepthResult failed = Result(5.0, true, false);
  failed.status = Status::NoCorridorFound("no lines");
  prior.Update(failed);  // Failed frames change nothing.
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.9);
}

TEST(CeilingHoldTest, BadThresholdsAreRejected) {
  for (const double bad : {-0.1, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    RecoverDepthOptions options;
    options.max_ceiling_disagreement = bad;
    std::string why;
    EXPECT_FALSE(options.Check(&why)) << bad;
    EXPECT_NE(why.find("max_ceiling_disagreement"), std::string::npos) << why;
  }
}

}  // namespace
}  // namespace corridor
