// A chosen junction's final fit on its edge pixels (RefineJunction, FloorSidePixels) against
// points placed on a known line: the line, ends, length and confidence are worked out by hand.

#include "perception/junction_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "perception/junction_detector.h"
#include "perception/line_segments.h"

namespace corridor {
namespace {

// v = 300 - 0.5 u: a left junction (rising to the right), its vanishing point up and right.
Eigen::Vector2d OnLine(double u) { return Eigen::Vector2d(u, 300 - 0.5 * u); }

TEST(FloorSidePixelsTest, KeepsThePointsLeftOfAndBelowTheVanishingPointInOrder) {
  const std::vector<Eigen::Vector2d> edges = {
      {10, 200}, {500, 200}, {10, 50}, {399, 100}, {400, 100}, {401, 150}};
  const Eigen::Vector2d vp(400, 100);
  const std::vector<Eigen::Vector2d> left = FloorSidePixels(edges, vp, true);
  ASSERT_EQ(left.size(), 3u);
  EXPECT_EQ(left[0], Eigen::Vector2d(10, 200));
  EXPECT_EQ(left[1], Eigen::Vector2d(399, 100));
  EXPECT_EQ(left[2], Eigen::Vector2d(400, 100));  // On the vanishing point's row and column.
  const std::vector<Eigen::Vector2d> right = FloorSidePixels(edges, vp, false);
  ASSERT_EQ(right.size(), 3u);
  EXPECT_EQ(right[0], Eigen::Vector2d(500, 200));
  EXPECT_EQ(right[1], Eigen::Vector2d(400, 100));
  EXPECT_EQ(right[2], Eigen::Vector2d(401, 150));
}

TEST(SupportPixelsTest, KeepsThePointsWithinTheDistanceOfTheLine) {
  const Eigen::Vector3d horizontal(0, 1, -100);  // v = 100.
  std::vector<Eigen::Vector2d> support;
  SupportPixels({{0, 100}, {5, 102}, {6, 102.5}, {7, 97.9}, {8, 98}}, horizontal, 2.0, &support);
  ASSERT_EQ(support.size(), 3u);
  EXPECT_EQ(support[0], Eigen::Vector2d(0, 100));
  EXPECT_EQ(support[1], Eigen::Vector2d(5, 102));
  EXPECT_EQ(support[2], Eigen::Vector2d(8, 98));
}

TEST(RefineJunctionTest, FitsThePointsOnItsFloorSideAndMeasuresTheirExtent) {
  // 201 points on the line from u = 100 to 300, 1.118 px apart along it (each in its own whole
  // pixel of length), the candidate 1 px below them; outliers 10 px off the line, and points on
  // the line beyond the vanishing point (u > 400), which belong to the other side.
  std::vector<Eigen::Vector2d> edges;
  for (int u = 100; u <= 300; ++u) edges.push_back(OnLine(u));
  for (int u = 120; u <= 280; u += 40) edges.push_back(OnLine(u) + Eigen::Vector2d(0, 10));
  for (int u = 410; u <= 450; ++u) edges.push_back(OnLine(u) + Eigen::Vector2d(0, 0.2));
  JunctionCandidate candidate{LineThrough(OnLine(100) + Eigen::Vector2d(0, 1),
                                          OnLine(300) + Eigen::Vector2d(0, 1)),
                              0.6};
  const Eigen::Vector2d vp = OnLine(400);
  const JunctionLine line = RefineJunction(candidate, edges, vp, true, 2.0, 2000);
  ASSERT_EQ(line.support.size(), 201u);
  for (int u : {100, 200, 300}) EXPECT_NEAR(line.line.dot(OnLine(u).homogeneous()), 0, 1e-9);
  EXPECT_NEAR(line.line.head<2>().norm(), 1, 1e-12);
  EXPECT_NEAR((line.near_end - OnLine(100)).norm(), 0, 1e-9);
  EXPECT_NEAR((line.far_end - OnLine(300)).norm(), 0, 1e-9);
  EXPECT_EQ(line.support_length, 201);
  // Boundary 0.6 times the support length over a quarter of the height (500 px).
  EXPECT_NEAR(line.confidence, 0.6 * 201 / 500.0, 1e-12);
  // A short image: the support is long enough, the confidence is the boundary score.
  EXPECT_NEAR(RefineJunction(candidate, edges, vp, true, 2.0, 480).confidence, 0.6, 1e-12);
}

TEST(RefineJunctionTest, ALineThatMovesFarFromTheCandidateStillGetsAllItsPixels) {
  // 501 points on the line from u = 100 to 600; the candidate leaves it from u = 100 on, 6 px
  // lower at u = 300 (15 px at u = 600). The first round (within 4 px of the candidate) takes the
  // points up to about u = 250, whose fit is the line itself; the next rounds must find all 501
  // on it, including those far from the candidate (u > ~550, more than 12 px from it).
  std::vector<Eigen::Vector2d> edges;
  for (int u = 100; u <= 600; ++u) edges.push_back(OnLine(u));
  JunctionCandidate candidate{LineThrough(OnLine(100), OnLine(300) + Eigen::Vector2d(0, 6)),
                              1.0};
  const JunctionLine line = RefineJunction(candidate, edges, OnLine(700), true, 2.0, 2000);
  ASSERT_EQ(line.support.size(), 501u);
  for (int u : {100, 350, 600}) EXPECT_NEAR(line.line.dot(OnLine(u).homogeneous()), 0, 1e-9);
  EXPECT_NEAR((line.near_end - OnLine(100)).norm(), 0, 1e-9);
  EXPECT_NEAR((line.far_end - OnLine(600)).norm(), 0, 1e-9);
}

TEST(RefineJunctionTest, TooFewSupportPixelsKeepTheCandidatesEnds) {
  // Five points on the candidate's line: too few to fit (FitLineLeastDistance needs 8) or to
  // measure an extent; the line and the ends stay the candidate's.
  std::vector<Eigen::Vector2d> edges;
  for (int u = 150; u <= 250; u += 25) edges.push_back(OnLine(u));
  JunctionCandidate candidate{LineThrough(OnLine(100), OnLine(300)), 1.5};
  const JunctionLine line = RefineJunction(candidate, edges, OnLine(400), true, 2.0, 480);
  ASSERT_EQ(line.support.size(), 2u);
  EXPECT_NEAR(line.line.dot(OnLine(200).homogeneous()), 0, 1e-9);
  EXPECT_NEAR((line.near_end - OnLine(100)).norm(), 0, 1e-9);
  EXPECT_NEAR((line.far_end - OnLine(300)).norm(), 0, 1e-9);
  EXPECT_EQ(line.support_length, 2);
  EXPECT_NEAR(line.confidence, 2 / 120.0, 1e-12);  // The boundary score is clamped to 1.
}

TEST(RefineJunctionTest, ALineBentAcrossTwoEdgesFollowsTheOneThatRunsTheWholeWay) {
  // The junction's pixels from u = 100 to 350, one per column; a grout line through the same
  // vanishing point on its floor side, 5 px lower at u = 100 (4.5 px across) and closing in on it
  // toward the vanishing point, from u = 100 to 250. The candidate is the grout line: its first
  // round (within 4 px) takes the grout's pixels near the camera and the junction's far off,
  // where the two are within 2 px, and a least-squares line bends between the two edges.
  const Eigen::Vector2d vp = OnLine(400);
  const auto grout = [](double u) -> Eigen::Vector2d {
    return OnLine(u) + Eigen::Vector2d(0, 5 * (400 - u) / 300);
  };
  std::vector<Eigen::Vector2d> edges;
  for (int u = 100; u <= 350; ++u) edges.push_back(OnLine(u));
  for (int u = 100; u <= 250; ++u) edges.push_back(grout(u));
  const JunctionCandidate candidate{LineThrough(grout(100), vp), 0.6};
  const JunctionLine line = RefineJunction(candidate, edges, vp, true, 2.0, 480);
  // On the junction, which runs the whole way, not between the two.
  for (int u : {100, 200, 300, 350}) {
    EXPECT_NEAR(line.line.dot(OnLine(u).homogeneous()), 0, 0.05) << u;
  }
  EXPECT_NEAR((line.near_end - OnLine(100)).norm(), 0, 0.5);
}

}  // namespace
}  // namespace corridor
