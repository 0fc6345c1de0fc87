// A sequence does not change a frame whose own evidence is strong: a frame not in doubt keeps its
// own ceiling (or none) over the trusted one whatever its sides say (HoldCeiling), and a kept one
// far from the trusted height contests it (SequencePrior); only a frame in doubt takes the trusted
// ceiling. A tracked frame whose own whole search is confirmed by its ceiling keeps that search's
// answer (OwnSearchKept). Numbers worked by hand: camera 0.5 m high; the recent frames trusted a
// ceiling at 2.9 m (2.4 m above the camera) with walls 2.2 m apart; this frame found its ceiling at
// 2.5 m (2.0 m above it, |log(2.0 / 2.4)| = 0.182) with walls 2.0 m apart.
#include <string>
#include <vector>

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
  // The right side's support, 0.30, is below 0.45: the sides cannot be compared (-1).
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
  EXPECT_NE(f.result.fallback.find("the previous frame's 2.90 m not held"), std::string::npos)
      << f.result.fallback;
}

// Every kind of untrusted ceiling: a strong side agreeing with the trusted height (2.85 m, 2.35 m
// above the camera, |log(2.35 / 2.4)| = 0.021), walls wider than the recent frames' (2.6 m), two
// strong sides that disagree (2.0 and 2.5 m: |log(1.5 / 2.0)| = 0.288 > 0.10), no ceiling found.
// A frame not in doubt keeps its own; a doubted one takes the trusted 2.9 m.
TEST(OwnEvidenceTest, OnlyAFrameInDoubtTakesTheTrustedCeiling) {
  const auto frames = [] {
    std::vector<Frame> made = {FoundCeiling(2.85, 0.8, 2.15, 0.30),
                               FoundCeiling(2.5, 0.8, 2.5, 0.30), FoundCeiling(2.0, 0.8, 2.5, 0.8),
                               FoundCeiling(0, 0, 0, 0)};
    made[1].geometry.SetWallDistances(1.3, 1.3);
    made[3].result.ceiling.found = false;
    made[3].geometry.ceiling_height = 0;
    return made;
  };
  ASSERT_NEAR(CeilingDisagreement(frames()[2].result.ceiling, 0.5, kMinSupport), 0.2877, 1e-4);
  int i = 0;
  for (Frame f : frames()) {
    const double own = f.geometry.ceiling_height;
    f.HoldTrusted(/*frame_doubted=*/false);
    EXPECT_FALSE(f.result.ceiling_held) << i;
    EXPECT_TRUE(f.result.ceiling_kept) << i;
    EXPECT_EQ(f.geometry.ceiling_height, own) << i;
    ++i;
  }
  i = 0;
  for (Frame f : frames()) {
    f.HoldTrusted(/*frame_doubted=*/true);
    EXPECT_TRUE(f.result.ceiling_held) << i;
    EXPECT_FALSE(f.result.ceiling_kept) << i;
    EXPECT_EQ(f.geometry.ceiling_height, 2.9) << i;
    EXPECT_NE(f.result.fallback.find("the previous frame's 2.90 m held"), std::string::npos)
        << f.result.fallback;
    ++i;
  }
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
