// A sequence does not change a frame whose own evidence is strong: a ceiling the frame found, whose
// two sides were only too weak to compare, is kept over the trusted one on a frame not in doubt
// unless a strong side of it confirms the trusted height (HoldCeiling), and then contests the
// trusted height (SequencePrior); a tracked frame whose own whole search is confirmed by its
// ceiling keeps that search's answer (OwnSearchKept). Numbers worked by hand: camera 0.5 m high;
// the recent frames trusted a ceiling at 2.9 m (2.4 m above the camera) with walls 2.2 m apart;
// this frame found its ceiling at 2.5 m (2.0 m above it, |log(2.0 / 2.4)| = 0.182) with walls
// 2.0 m apart.
#include <string>

#include <gtest/gtest.h>

#include "pipeline/ceiling_agreement.h"
#include "pipeline/sequence_holds.h"
#include "pipeline/sequence_prior.h"

namespace corridor {
namespace {

constexpr double kMaxDisagreement = 0.10;  // RecoverDepthOptions::max_ceiling_disagreement.
constexpr double kMinSupport = 0.45;       // The ceiling's min_support.

CorridorGeometry Trusted() {
  CorridorGeometry previous;
  previous.camera_height = 0.5;
  previous.ceiling_height = 2.9;
  previous.SetWallDistances(1.1, 1.1);
  return previous;
}

struct Frame {
  CorridorGeometry geometry;
  RecoverDepthResult result;
  // HoldCeiling against the trusted ceiling (Trusted()).
  void HoldTrusted(bool frame_doubted) {
    const CorridorGeometry previous = Trusted();
    HoldCeiling(&previous, kMaxDisagreement, kMinSupport, frame_doubted, &geometry, &result);
  }
};

// A frame whose ceiling search found 2.5 m, with each side's height and support as given.
Frame FoundCeiling(double left_height, double left_support, double right_height,
                   double right_support) {
  Frame f;
  f.geometry.camera_height = 0.5;
  f.geometry.ceiling_height = 2.5;
  f.geometry.SetWallDistances(1.0, 1.0);
  f.result.ceiling.found = true;
  f.result.ceiling.height = 2.5;
  f.result.ceiling.side_height[0] = left_height;
  f.result.ceiling.side_height[1] = right_height;
  f.result.ceiling.side_support[0] = left_support;
  f.result.ceiling.side_support[1] = right_support;
  return f;
}

TEST(OwnEvidenceTest, ACeilingWhoseSidesAreTooWeakToCompareIsKeptOnAFrameNotInDoubt) {
  // The right side's support, 0.30, is below 0.45: the sides cannot be compared (-1). The strong
  // left side, 2.5 m, is 0.182 (|log ratio|) from the trusted 2.9 m, more than 0.10: no
  // confirmation.
  Frame f = FoundCeiling(2.5, 0.8, 2.5, 0.30);
  ASSERT_EQ(CeilingDisagreement(f.result.ceiling, 0.5, kMinSupport), -1);
  const CorridorGeometry previous = Trusted();
  EXPECT_TRUE(CeilingHoldConsidered(&previous, kMaxDisagreement, kMinSupport, f.geometry,
                                    &f.result));
  f.HoldTrusted(/*frame_doubted=*/false);
  EXPECT_FALSE(f.result.ceiling_held);
  EXPECT_FALSE(f.result.ceiling_trusted);
  EXPECT_EQ(f.geometry.ceiling_height, 2.5);
  EXPECT_TRUE(f.result.ceiling_kept);
  EXPECT_NE(f.result.fallback.find("the frame's own 2.50 m kept"), std::string::npos)
      << f.result.fallback;
}

TEST(OwnEvidenceTest, AStrongSideThatAgreesWithTheTrustedCeilingConfirmsIt) {
  // The strong left side at 2.85 m: 2.35 m above the camera, |log(2.35 / 2.4)| = 0.021 <= 0.10.
  // The weak right one (support 0.30) at 2.15 m pulled the frame's ceiling down to 2.5 m.
  Frame f = FoundCeiling(2.85, 0.8, 2.15, 0.30);
  f.HoldTrusted(/*frame_doubted=*/false);
  EXPECT_TRUE(f.result.ceiling_held);
  EXPECT_EQ(f.geometry.ceiling_height, 2.9);
  // The same height on the weak side confirms nothing.
  Frame weak = FoundCeiling(2.15, 0.8, 2.85, 0.30);
  weak.HoldTrusted(/*frame_doubted=*/false);
  EXPECT_FALSE(weak.result.ceiling_held);
  EXPECT_EQ(weak.geometry.ceiling_height, 2.5);
}

TEST(OwnEvidenceTest, AKeptCeilingFarFromTheTrustedOneContestsIt) {
  SequencePrior prior;
  RecoverDepthResult trusted;
  trusted.status = Status::Ok();
  trusted.has_geometry = true;
  trusted.geometry = Trusted();
  trusted.ceiling.found = true;
  trusted.ceiling.height = 2.9;
  trusted.ceiling_trusted = true;
  prior.Update(trusted);
  ASSERT_NE(prior.Previous(), nullptr);
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.9);

  // Kept at 2.8 m: 2.3 m above the camera, |log(2.3 / 2.4)| = 0.043, within 0.15: still 2.9 m.
  RecoverDepthResult near = trusted;
  near.ceiling_trusted = false;
  near.ceiling_kept = true;
  near.geometry.ceiling_height = 2.8;
  near.ceiling.height = 2.8;
  prior.Update(near);
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.9);

  // Kept at 2.5 m: 0.182 from it, beyond 0.15: no height is carried.
  RecoverDepthResult far = near;
  far.geometry.ceiling_height = 2.5;
  far.ceiling.height = 2.5;
  prior.Update(far);
  ASSERT_NE(prior.Previous(), nullptr);
  EXPECT_FALSE(prior.Previous()->HasCeiling());

  // A frame merely not trusted (its ceiling not kept against a hold) contests nothing.
  prior.Update(trusted);
  RecoverDepthResult untrusted = far;
  untrusted.ceiling_kept = false;
  prior.Update(untrusted);
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.9);

  // The next frame whose sides agree is trusted again.
  prior.Update(trusted);
  EXPECT_EQ(prior.Previous()->ceiling_height, 2.9);
}

TEST(OwnEvidenceTest, AWiderFrameTakesTheTrustedCeiling) {
  // The frame's walls 2.6 m apart against the recent frames' 2.2 m: its ceiling, off from the
  // trusted one, came with walls put too far.
  Frame f = FoundCeiling(2.5, 0.8, 2.5, 0.30);
  f.geometry.SetWallDistances(1.3, 1.3);
  f.HoldTrusted(/*frame_doubted=*/false);
  EXPECT_TRUE(f.result.ceiling_held);
  EXPECT_FALSE(f.result.ceiling_kept);
  EXPECT_EQ(f.geometry.ceiling_height, 2.9);
}

TEST(OwnEvidenceTest, ADoubtedFrameTakesTheTrustedCeiling) {
  Frame f = FoundCeiling(2.5, 0.8, 2.5, 0.30);
  f.HoldTrusted(/*frame_doubted=*/true);
  EXPECT_TRUE(f.result.ceiling_held);
  EXPECT_EQ(f.geometry.ceiling_height, 2.9);
}

TEST(OwnEvidenceTest, SidesThatDisagreeAreEvidenceAgainstTheFramesCeiling) {
  // Both sides strong: 2.0 and 2.5 m, i.e. 1.5 and 2.0 m above the camera, |log(1.5 / 2.0)| =
  // 0.288 > 0.10: a wall is wrong, and the trusted ceiling is held even on a frame not in doubt.
  Frame f = FoundCeiling(2.0, 0.8, 2.5, 0.8);
  ASSERT_NEAR(CeilingDisagreement(f.result.ceiling, 0.5, kMinSupport), 0.2877, 1e-4);
  f.HoldTrusted(/*frame_doubted=*/false);
  EXPECT_TRUE(f.result.ceiling_held);
  EXPECT_EQ(f.geometry.ceiling_height, 2.9);
}

TEST(OwnEvidenceTest, AFrameWithoutACeilingTakesTheTrustedOne) {
  Frame f = FoundCeiling(0, 0, 0, 0);
  f.result.ceiling.found = false;
  f.geometry.ceiling_height = 0;
  f.HoldTrusted(/*frame_doubted=*/false);
  EXPECT_TRUE(f.result.ceiling_held);
  EXPECT_EQ(f.geometry.ceiling_height, 2.9);
}

TEST(OwnEvidenceTest, AgreeingSidesAreTrustedAndNothingIsHeld) {
  // 2.45 and 2.55 m: 1.95 and 2.05 m above the camera, |log(1.95 / 2.05)| = 0.050 <= 0.10.
  Frame f = FoundCeiling(2.45, 0.8, 2.55, 0.8);
  const CorridorGeometry previous = Trusted();
  EXPECT_FALSE(CeilingHoldConsidered(&previous, kMaxDisagreement, kMinSupport, f.geometry,
                                     &f.result));
  EXPECT_TRUE(f.result.ceiling_trusted);
  f.HoldTrusted(/*frame_doubted=*/true);
  EXPECT_FALSE(f.result.ceiling_held);
  EXPECT_EQ(f.geometry.ceiling_height, 2.5);
}

RecoverDepthResult OwnSearch(bool ok, bool ceiling_trusted) {
  RecoverDepthResult own;
  own.status = ok ? Status::Ok() : Status::LowConfidence("confidence 0.40 is below 0.60");
  own.has_geometry = ok;
  own.ceiling_trusted = ceiling_trusted;
  return own;
}

TEST(OwnEvidenceTest, AnOwnSearchConfirmedByItsCeilingIsKept) {
  const RecoverDepthOptions options;  // The ceiling is searched.
  EXPECT_TRUE(OwnSearchKept(options, OwnSearch(true, true)));
  EXPECT_FALSE(OwnSearchKept(options, OwnSearch(true, false)));   // Its ceiling does not confirm.
  EXPECT_FALSE(OwnSearchKept(options, OwnSearch(false, false)));  // Refused alone.
  RecoverDepthResult tracked = OwnSearch(true, true);
  tracked.junctions_tracked = true;  // Not a whole search.
  EXPECT_FALSE(OwnSearchKept(options, tracked));
}

TEST(OwnEvidenceTest, WithoutACeilingSearchNothingConfirmsTheOwnSearch) {
  RecoverDepthOptions given;
  given.ceiling_height = 2.7;
  EXPECT_FALSE(OwnSearchKept(given, OwnSearch(true, true)));
  RecoverDepthOptions none;
  none.estimate_ceiling = false;
  EXPECT_FALSE(OwnSearchKept(none, OwnSearch(true, true)));
}

}  // namespace
}  // namespace corridor
