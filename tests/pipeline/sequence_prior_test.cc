// The width a sequence carries: the median of the recent measured widths, so that one frame's
// wrong wide width is not held over the right frames after it, and the recent widths start again
// when a held width is let go. Widths written out here; the medians worked out by hand.
#include "pipeline/sequence_prior.h"

#include <gtest/gtest.h>

namespace corridor {
namespace {

RecoverDepthResult Frame(double width, bool held = false) {
  RecoverDepthResult r;
  r.status = Status::Ok();
  r.has_geometry = true;
  r.geometry.width = width;
  r.geometry.camera_height = 0.4;
  r.width_held = held;
  return r;
}

TEST(SequencePriorTest, OneWideFrameDoesNotBecomeTheWidth) {
  SequencePrior prior;
  EXPECT_EQ(prior.Previous(), nullptr);
  prior.Update(Frame(3.10));
  ASSERT_NE(prior.Previous(), nullptr);
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 3.10);
  prior.Update(Frame(3.08));
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 3.08);  // {3.08, 3.10}: the lower middle.
  prior.Update(Frame(3.11));
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 3.10);
  prior.Update(Frame(3.74));  // A line beyond the wall: {3.08, 3.10, 3.11, 3.74}.
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 3.10);
  prior.Update(Frame(3.75));  // {3.08, 3.10, 3.11, 3.74, 3.75}.
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 3.11);
  prior.Update(Frame(3.09));  // 3.10 drops out: {3.08, 3.09, 3.11, 3.74, 3.75}.
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 3.11);
}

TEST(SequencePriorTest, HeldWidthsAreNotRecentWidths) {
  SequencePrior prior;
  prior.Update(Frame(2.0));
  prior.Update(Frame(2.0, /*held=*/true));  // Held at 2.0: the 1.6 measured is not recorded.
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 2.0);
  prior.Update(Frame(2.2));
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 2.0);  // {2.0, 2.2}: the lower middle.
}

TEST(SequencePriorTest, KeptNarrowWidthsAreNotRecentWidths) {
  SequencePrior prior;
  prior.Update(Frame(2.6));
  prior.Update(Frame(2.5));
  RecoverDepthResult kept = Frame(2.0);  // Much narrower, kept by a confident frame.
  kept.width_kept = true;
  prior.Update(kept);
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 2.5);  // {2.5, 2.6}: the 2.0 is not recorded.
  prior.Update(Frame(2.4));
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 2.5);  // {2.4, 2.5, 2.6}; with 2.0: 2.4.
  for (int i = 0; i < SequencePrior::kMaxHeld; ++i) prior.Update(kept);
  EXPECT_EQ(prior.Previous(), nullptr);  // Kept three in a row: let go, as held widths are.
}

TEST(SequencePriorTest, ALetGoWidthStartsTheRecentWidthsAgain) {
  SequencePrior prior;
  for (int i = 0; i < 3; ++i) prior.Update(Frame(3.0));
  for (int i = 0; i < SequencePrior::kMaxHeld; ++i) {
    ASSERT_NE(prior.Previous(), nullptr);
    prior.Update(Frame(3.0, /*held=*/true));  // The corridor narrowed; the width was held.
  }
  EXPECT_EQ(prior.Previous(), nullptr);  // Let go for one frame.
  prior.Update(Frame(2.0));
  ASSERT_NE(prior.Previous(), nullptr);
  EXPECT_DOUBLE_EQ(prior.Previous()->width, 2.0);  // Not the median with the 3.0s.
}

// A frame with its own ceiling measurement (found), trusted or not.
RecoverDepthResult CeilingFrame(double height, bool trusted) {
  RecoverDepthResult r = Frame(2.0);
  r.geometry.camera_height = 0.5;
  r.geometry.ceiling_height = height;
  r.ceiling.found = true;
  r.ceiling.height = height;
  r.ceiling_trusted = trusted;
  return r;
}

TEST(SequencePriorTest, OneTrustedCeilingThatTheRecentFramesOutvoteIsNotCarried) {
  SequencePrior prior;
  for (int i = 0; i < 3; ++i) prior.Update(CeilingFrame(2.5, /*trusted=*/false));
  EXPECT_EQ(prior.Previous()->ceiling_height, 0.0);  // Nothing trusted yet: nothing carried.
  // Both sides agree on a window band's top, 1.9 m: 1.4 m above the camera against 2.0 m.
  prior.Update(CeilingFrame(1.9, /*trusted=*/true));
  // The recent heights {2.5, 2.5, 2.5, 1.9}: their median 2.5 is |log(2.0 / 1.4)| = 0.36 away.
  EXPECT_DOUBLE_EQ(prior.Previous()->ceiling_height, 2.5);
}

TEST(SequencePriorTest, ATrustedCeilingTheRecentFramesAgreeWithIsCarried) {
  SequencePrior prior;
  prior.Update(CeilingFrame(2.6, false));
  prior.Update(CeilingFrame(2.8, false));
  prior.Update(CeilingFrame(2.7, true));
  // {2.6, 2.8, 2.7}: median 2.7, the trusted one.
  EXPECT_DOUBLE_EQ(prior.Previous()->ceiling_height, 2.7);
  prior.Update(CeilingFrame(2.3, false));  // Untrusted: 2.7 stays ({2.3, 2.6, 2.7, 2.8} -> 2.6,
                                           // |log(2.1 / 2.2)| = 0.05 away).
  EXPECT_DOUBLE_EQ(prior.Previous()->ceiling_height, 2.7);
}

}  // namespace
}  // namespace corridor
