// The junction candidates' scene prior (MakeJunctionScenePrior, AddJunctionCandidates) on lines
// placed by hand: bounds worked out from the options, sides from the slopes.

#include "perception/junction_candidates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

namespace corridor {
namespace {

TEST(JunctionScenePriorTest, BoundsComeFromTheImageSize) {
  JunctionDetectorOptions options;
  options.min_length_fraction = 0.1;
  options.max_length_fraction = 0.5;
  options.min_inclination_deg = 8;
  options.max_inclination_deg = 80;
  JunctionScenePrior prior = MakeJunctionScenePrior(options, 640, 480);
  EXPECT_DOUBLE_EQ(prior.min_length, 48);   // 0.1 of the height.
  EXPECT_DOUBLE_EQ(prior.max_length, 400);  // Half the 800 px diagonal.
  EXPECT_DOUBLE_EQ(prior.min_inclination_deg, 8);
  EXPECT_DOUBLE_EQ(prior.max_inclination_deg, 80);
  // No length limit; the paper's steepest junction, 90 deg - atan(480 / 640) = 53.13 deg.
  options.max_length_fraction = 0;
  options.max_inclination_deg = -1;
  prior = MakeJunctionScenePrior(options, 640, 480);
  EXPECT_GT(prior.max_length, 1e100);
  EXPECT_NEAR(prior.max_inclination_deg, 53.130102354, 1e-8);
}

TEST(JunctionCandidatesTest, ThePriorKeepsLinesOfJunctionLengthAndInclinationBySide) {
  const cv::Mat color(480, 640, CV_8UC3, cv::Scalar(60, 90, 120));
  FloorCues cues;
  cues.roi = color.rowRange(240, 480);
  cues.floor = SampleFloor(cues.roi, 240);
  cues.roi_top = 240;
  JunctionScenePrior prior;
  prior.min_length = 48;
  prior.max_length = 400;
  prior.min_inclination_deg = 8;
  prior.max_inclination_deg = 80;
  const std::vector<MergedLine> lines = {
      LineThrough({100, 470}, {300, 300}),  // Left (rises to the right), 262 px, 40 deg.
      LineThrough({600, 470}, {400, 300}),  // Right.
      LineThrough({100, 470}, {130, 450}),  // Too short (36 px).
      LineThrough({0, 479}, {500, 250}),    // Too long (550 px).
      LineThrough({100, 470}, {400, 440}),  // Too flat (5.7 deg).
      LineThrough({300, 470}, {310, 300}),  // Too steep (86.6 deg).
      LineThrough({560, 470}, {500, 420}),  // Right, 78 px.
  };
  PairSearch search;
  AddJunctionCandidates(lines, prior.min_length, prior, cues, &search);
  ASSERT_EQ(search.left.size(), 1u);
  EXPECT_EQ(search.left[0].line.start, lines[0].start);
  ASSERT_EQ(search.right.size(), 2u);
  EXPECT_EQ(search.right[0].line.start, lines[1].start);
  EXPECT_EQ(search.right[1].line.start, lines[6].start);
  for (const auto& side : {search.left, search.right}) {
    for (const JunctionCandidate& c : side) EXPECT_TRUE(c.boundary >= 0 && c.boundary <= 1);
  }
  // A longer shortest line (the second look's) leaves the 78 px one out.
  PairSearch longer;
  AddJunctionCandidates(lines, 100, prior, cues, &longer);
  EXPECT_EQ(longer.left.size(), 1u);
  EXPECT_EQ(longer.right.size(), 1u);
}

}  // namespace
}  // namespace corridor
