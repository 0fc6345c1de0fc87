// The one-junction fallback's stages: which line is the floor's edge (OutermostFloorEdge) and
// where the other lines meet it (VoteSingleVanishingPoint), on lines placed by hand.

#include "perception/single_junction.h"

#include <gtest/gtest.h>

#include <vector>

#include "perception/line_segments.h"

namespace corridor {
namespace {

constexpr int kHeight = 480;

// A candidate whose line meets the bottom row (v = 480) at u = bottom_u and rises to the right
// with slope -0.5 (a left junction), or falls (a right one).
JunctionCandidate Candidate(double bottom_u, double boundary, bool left = true) {
  const double du = left ? 200 : -200;
  return {LineThrough({bottom_u, kHeight}, {bottom_u + du, kHeight - 100}), boundary};
}

TEST(OutermostFloorEdgeTest, TakesTheOutermostLineThatLooksLikeTheFloorsEdge) {
  // Boundary 0.35 is under half the best (0.8): not the floor's edge, though it is outermost.
  const std::vector<JunctionCandidate> left = {Candidate(50, 0.8), Candidate(10, 0.35),
                                               Candidate(30, 0.5)};
  EXPECT_EQ(OutermostFloorEdge(left, true, kHeight), 2);
  const std::vector<JunctionCandidate> right = {Candidate(600, 0.5, false),
                                                Candidate(630, 0.2, false),
                                                Candidate(590, 0.6, false)};
  EXPECT_EQ(OutermostFloorEdge(right, false, kHeight), 0);
}

TEST(OutermostFloorEdgeTest, NoneWhenNoLineHasFloorBelowIt) {
  EXPECT_EQ(OutermostFloorEdge({}, true, kHeight), -1);
  // Under the absolute floor of 0.3, whatever the best is.
  EXPECT_EQ(OutermostFloorEdge({Candidate(50, 0.25), Candidate(10, 0.29)}, true, kHeight), -1);
}

// A left junction from (100, 400) to (300, 250); the corridor's lines meet it at (400, 175).
JunctionLine Junction() {
  JunctionLine j;
  const MergedLine m = LineThrough({100, 400}, {300, 250});
  j.line = m.line;
  j.near_end = {100, 400};
  j.far_end = {300, 250};
  return j;
}

TEST(VoteSingleVanishingPointTest, TheLinesThroughOnePointAboveTheSupportVoteForIt) {
  const JunctionLine junction = Junction();
  const MergedLine chosen = LineThrough({100, 400}, {300, 250});
  const std::vector<MergedLine> lines = {
      LineThrough({600, 400}, {400, 175}),  // The other junction.
      LineThrough({100, 0}, {400, 175}),    // A ceiling line.
      LineThrough({700, 50}, {400, 175}),   // A door top on the other wall.
      LineThrough({200, 100}, {200, 479}),  // A door frame: crosses on the support.
      LineThrough({0, 500}, {400, 180}),    // Crosses it at (500, 100), within 5 degrees of it.
      LineThrough({500, 0}, {400, 175}),    // Through the point, but shorter than `shortest`.
  };
  Eigen::Vector2d vp(-1, -1);
  int votes = -1;
  ASSERT_TRUE(VoteSingleVanishingPoint(junction, chosen, lines, 210, kHeight, &vp, &votes));
  EXPECT_NEAR(vp.x(), 400, 1e-9);
  EXPECT_NEAR(vp.y(), 175, 1e-9);
  EXPECT_EQ(votes, 3);
}

TEST(VoteSingleVanishingPointTest, DisagreeingOrTooFewCrossingsVoteForNothing) {
  const JunctionLine junction = Junction();
  const MergedLine chosen = LineThrough({100, 400}, {300, 250});
  Eigen::Vector2d vp(-1, -1);
  int votes = -1;
  // One crossing.
  EXPECT_FALSE(VoteSingleVanishingPoint(junction, chosen, {LineThrough({600, 400}, {400, 175})},
                                        0, kHeight, &vp, &votes));
  // Three crossings far apart along the line (more than 3% of the height, 14.4 px).
  EXPECT_FALSE(VoteSingleVanishingPoint(junction, chosen,
                                        {LineThrough({600, 400}, {400, 175}),
                                         LineThrough({600, 400}, {480, 115}),
                                         LineThrough({600, 400}, {560, 55})},
                                        0, kHeight, &vp, &votes));
  EXPECT_EQ(vp, Eigen::Vector2d(-1, -1));
  EXPECT_EQ(votes, -1);
}

}  // namespace
}  // namespace corridor
