// Which wall a held width keeps: the one whose ceiling, searched on its side alone, agrees with
// the trusted ceiling carried by the sequence (and by less than a wrong wall puts it off); without
// both sides' heights, or with both sides off, the one that moved less since the recent frames;
// and only a doubted frame is held. Geometry worked out by hand: camera 0.5 m high, ceiling 2.5 m,
// walls 1.0 m either side; this frame puts its left wall at 0.6 m (a line inside the floor), so
// that side's ceiling comes out at 0.5 + 2.0 * 0.6 / 1.0 = 1.7 m, 0.51 (|log ratio|) off.
#include <utility>

#include <gtest/gtest.h>

#include "pipeline/sequence_holds.h"

namespace corridor {
namespace {

struct Held {
  CorridorGeometry geometry;
  RecoverDepthResult result;
};

Held HoldWithSideHeights(double left_height, double right_height, bool frame_doubted = true,
                         double left_line = 0.5) {
  CorridorGeometry previous;  // The recent width and trusted ceiling; the camera was 0.35 m left.
  previous.camera_height = 0.5;
  previous.ceiling_height = 2.5;
  previous.SetWallDistances(0.65, 1.35);
  Held held;
  held.geometry.camera_height = 0.5;
  held.geometry.SetWallDistances(0.6, 1.0);  // 1.6 m: much narrower than 2.0 m.
  held.result.ceiling.side_height[0] = left_height;
  held.result.ceiling.side_height[1] = right_height;
  held.result.junctions.left.confidence = left_line;
  held.result.junctions.right.confidence = 0.5;
  HoldWidth(previous, 0.15, frame_doubted, &held.geometry, &held.result);
  return held;
}

TEST(HeldWallTest, TheWallWhoseCeilingAgreesIsKept) {
  const Held held = HoldWithSideHeights(1.7, 2.5);
  ASSERT_TRUE(held.result.width_held);
  EXPECT_DOUBLE_EQ(held.geometry.width, 2.0);
  EXPECT_DOUBLE_EQ(held.geometry.RightDistance(), 1.0);
  EXPECT_NEAR(held.geometry.LeftDistance(), 1.0, 1e-12);
  EXPECT_NE(held.result.fallback.find("right wall kept"), std::string::npos)
      << held.result.fallback;
}

TEST(HeldWallTest, WithoutBothSidesTheWallThatMovedLessIsKept) {
  // The left wall moved 0.05 m since the recent frames, the right one 0.35 m.
  const Held held = HoldWithSideHeights(0.0, 2.5);
  ASSERT_TRUE(held.result.width_held);
  EXPECT_DOUBLE_EQ(held.geometry.width, 2.0);
  EXPECT_NEAR(held.geometry.LeftDistance(), 0.6, 1e-12);
  EXPECT_NE(held.result.fallback.find("left wall kept"), std::string::npos)
      << held.result.fallback;
}

TEST(HeldWallTest, SidesThatBothNearlyAgreeLeaveItToTheWallThatMovedLess) {
  // 2.4 m and 2.6 m: 5% below and above the trusted 2.0 m above the camera, neither a wrong wall.
  const Held held = HoldWithSideHeights(2.4, 2.6);
  ASSERT_TRUE(held.result.width_held);
  EXPECT_NEAR(held.geometry.LeftDistance(), 0.6, 1e-12);
}

TEST(HeldWallTest, AConfidentFrameIsNeverHeld) {
  // The frame's own evidence strong (not doubted): with its ceiling's clear answer (the left side
  // 0.51 off: a line inside the floor, or a box's face before the wall), without one (one side not
  // measured), or with both sides nearly agreeing, it keeps its own 1.6 m, and the note says why.
  const std::pair<double, double> cases[] = {{1.7, 2.5}, {0.0, 2.5}, {2.4, 2.6}};
  const char* why[] = {"as a box's face standing before the wall would",
                       "ceiling does not say which wall", "ceiling does not say which wall"};
  for (int i = 0; i < 3; ++i) {
    const Held kept = HoldWithSideHeights(cases[i].first, cases[i].second, false);
    EXPECT_FALSE(kept.result.width_held) << i;
    EXPECT_TRUE(kept.result.width_kept) << i;
    EXPECT_DOUBLE_EQ(kept.geometry.width, 1.6) << i;
    EXPECT_DOUBLE_EQ(kept.geometry.LeftDistance(), 0.6) << i;
    EXPECT_NE(kept.result.fallback.find("own evidence is strong"), std::string::npos)
        << kept.result.fallback;
    EXPECT_NE(kept.result.fallback.find(why[i]), std::string::npos) << kept.result.fallback;
  }
}

TEST(HeldWallTest, ASideOffByAWrongWallsAmountDoesNotSayWhichWall) {
  // Left 1.7 m: 1.2 m above the camera against the trusted 2.0 m, |log 0.6| = 0.51 off. Right
  // 2.2 m: 1.7 m, |log 0.85| = 0.16 off, under half the left's but beyond log 1.15 = 0.14: that
  // wall is wrong too (both lines inside the floor). No answer: a doubted frame is held by the wall
  // that moved less (the left one, 0.05 m against 0.35 m), a confident frame keeps its 1.6 m.
  const Held doubted = HoldWithSideHeights(1.7, 2.2);
  ASSERT_TRUE(doubted.result.width_held);
  EXPECT_NEAR(doubted.geometry.LeftDistance(), 0.6, 1e-12);
  EXPECT_NEAR(doubted.geometry.RightDistance(), 1.4, 1e-12);
  EXPECT_NE(doubted.result.fallback.find("moved less"), std::string::npos)
      << doubted.result.fallback;
  const Held confident = HoldWithSideHeights(1.7, 2.2, false);
  EXPECT_FALSE(confident.result.width_held);
  EXPECT_DOUBLE_EQ(confident.geometry.width, 1.6);
  EXPECT_NE(confident.result.fallback.find("ceiling does not say which wall"), std::string::npos)
      << confident.result.fallback;
  // Right 2.4 m: 1.9 m, |log 0.95| = 0.05 off: that side agrees, its wall is kept (doubted frame).
  const Held answered = HoldWithSideHeights(1.7, 2.4);
  ASSERT_TRUE(answered.result.width_held);
  EXPECT_NEAR(answered.geometry.RightDistance(), 1.0, 1e-12);
  EXPECT_NEAR(answered.geometry.LeftDistance(), 1.0, 1e-12);
}

TEST(HeldWallTest, ADoubtedFrameLosesEvenAStrongLine) {
  // The ceiling says the left wall is wrong and its line is strong (0.8, the foot of a box's
  // face): a confident frame keeps it, with the line named; a doubted one is held.
  const Held kept = HoldWithSideHeights(1.7, 2.5, false, 0.8);
  EXPECT_FALSE(kept.result.width_held);
  EXPECT_DOUBLE_EQ(kept.geometry.LeftDistance(), 0.6);
  EXPECT_NE(kept.result.fallback.find("left junction line, 0.80"), std::string::npos)
      << kept.result.fallback;
  const Held held = HoldWithSideHeights(1.7, 2.5, true, 0.8);
  ASSERT_TRUE(held.result.width_held);
  EXPECT_NEAR(held.geometry.LeftDistance(), 1.0, 1e-12);
}

TEST(HeldWallTest, AFrameIsInDoubtOnItsOwnConfidenceCeilingOrTrackedLines) {
  // min_confidence 0.6; sides measurably disagreeing beyond log(1.06) = 0.058.
  EXPECT_FALSE(FrameInDoubt(1.0, 0.6, -1, 0.058, false));    // Sides not comparable: no doubt.
  EXPECT_FALSE(FrameInDoubt(0.6, 0.6, 0.05, 0.058, false));  // At the threshold, sides agreeing.
  EXPECT_TRUE(FrameInDoubt(0.59, 0.6, -1, 0.058, false));
  EXPECT_TRUE(FrameInDoubt(1.0, 0.6, 0.07, 0.058, false));
  EXPECT_TRUE(FrameInDoubt(1.0, 0.6, -1, 0.058, true));
}

TEST(HeldWallTest, ARescuedFrameSaysSo) {
  RecoverDepthResult result;
  result.width_held = true;
  result.confidence = 0.9;  // The held layout's confidence.
  ASSERT_TRUE(NoteRescue(0.54, 0.6, &result));
  EXPECT_NE(result.fallback.find("rescued by the held width: the frame's own confidence 0.54 is "
                                 "below 0.60"),
            std::string::npos)
      << result.fallback;
  // Not held, already confident alone, or still below the threshold: no rescue.
  RecoverDepthResult other = result;
  other.fallback.clear();
  other.width_held = false;
  EXPECT_FALSE(NoteRescue(0.54, 0.6, &other));
  other.width_held = true;
  EXPECT_FALSE(NoteRescue(0.8, 0.6, &other));
  other.confidence = 0.5;
  EXPECT_FALSE(NoteRescue(0.54, 0.6, &other));
  EXPECT_TRUE(other.fallback.empty()) << other.fallback;
}

}  // namespace
}  // namespace corridor
