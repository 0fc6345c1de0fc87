// The ceiling's split (pipeline/ceiling_split.h): walls that the two ceiling sides contradict,
// where a wall moved to agree with them stands on a junction that follows edges, give the sides'
// ratio; walls the ceiling confirms, or a disagreement below the threshold, give -1. Truth from
// the generator: its frames and their true geometry.
#include "pipeline/ceiling_split.h"

#include <cmath>

#include <gtest/gtest.h>

#include "perception/ceiling_detector.h"
#include "pipeline/frame_confidence.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

using testing_util::WithWallScaled;

// A plain corridor with its ceiling junctions in view.
synth::Frame SplitFrame(const Camera& camera) {
  return testing_util::RenderCorridorFrame(camera, 2.4, 2.7, 3,
                                           synth::CameraPose{0.05, 0.04, 0.25, 0.66, 3.0}, 0.0);
}

// The split of `g` on `frame`, with the ceiling searched for g as the pipeline searches it.
double SplitOf(const synth::Frame& frame, const Camera& camera, const CorridorGeometry& g,
               const CeilingSplitOptions& options = CeilingSplitOptions()) {
  CeilingEstimate ceiling;
  EXPECT_TRUE(DetectCeiling(frame.bgr, camera, g, CeilingDetectorOptions(), &ceiling).ok());
  return CeilingSplit(frame.bgr, camera, g, ceiling, CeilingDetectorOptions(), options);
}

TEST(CeilingSplitTest, TheTrueWallsHaveNoSplit) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = SplitFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  EXPECT_EQ(SplitOf(frame, camera, frame.truth), -1);
}

// One wall put too far by 1.3 (a rail's or a baseboard's top taken for its junction: the wall
// distance scales by h / (h - b)), or too near by 1 / 1.3 (a line inside the floor): its ceiling
// side's height above the camera scales alike, and the true junction lies where the move that
// agrees with the other side would put it. The split is that ratio.
TEST(CeilingSplitTest, AWallTooFarOrTooNearGivesTheSidesRatio) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = SplitFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  for (const int side : {0, 1}) {
    for (const double factor : {1.3, 1 / 1.3}) {
      const double split = SplitOf(frame, camera, WithWallScaled(frame.truth, side, factor));
      EXPECT_NEAR(split, std::log(1.3), 0.05) << side << " " << factor;
    }
  }
}

// A disagreement below min_disagreement (10% against 18%) is not a split; with a lower threshold
// the same walls are.
TEST(CeilingSplitTest, ASmallDisagreementIsNoSplit) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = SplitFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry g = WithWallScaled(frame.truth, 1, 1.1);
  EXPECT_EQ(SplitOf(frame, camera, g), -1);
  CeilingSplitOptions low;
  low.min_disagreement = 0.05;
  EXPECT_NEAR(SplitOf(frame, camera, g, low), std::log(1.1), 0.04);
}

// Without a line where either move would put a junction (both moves land beside the true walls,
// on the walls' plain faces or the bare floor), the disagreement does not say which layout is
// right: no split. Here one wall is too far by 1.5 and the other too near by 0.85, so that the
// ceiling's ratio, about 1.76, points at neither true junction.
TEST(CeilingSplitTest, NoLineWhereAMoveWouldPutTheJunctionIsNoSplit) {
  const Camera camera = synth::PaperCamera(0.66);
  const synth::Frame frame = SplitFrame(camera);
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry g = WithWallScaled(WithWallScaled(frame.truth, 0, 1.5), 1, 0.85);
  EXPECT_EQ(SplitOf(frame, camera, g), -1);
  // The premise: the sides are plainly seen and split; only the line for a move is missing.
  CeilingSplitOptions any_line;
  any_line.min_alternative_support = 1e-6;
  EXPECT_NEAR(SplitOf(frame, camera, g, any_line), std::log(1.5 / 0.85), 0.05);
}

TEST(CeilingSplitTest, OptionsAreChecked) {
  CeilingSplitOptions o;
  std::string why;
  EXPECT_TRUE(o.Check(&why));
  o.min_visible_support = 0;
  EXPECT_FALSE(o.Check(&why));
  EXPECT_NE(why.find("min_visible_support"), std::string::npos) << why;
  o = CeilingSplitOptions();
  o.min_disagreement = -1;
  EXPECT_FALSE(o.Check(&why));
  EXPECT_NE(why.find("min_disagreement"), std::string::npos) << why;
}

// A split alone refuses the frame (factor 0.5 against the default min_confidence 0.6), and says
// why.
TEST(CeilingSplitTest, ASplitAloneRefusesTheFrame) {
  FrameEvidence e;
  e.junction[0] = e.junction[1] = 0.5;
  e.ceiling_split = std::log(1.25);
  std::string why;
  EXPECT_DOUBLE_EQ(FrameConfidence(e, &why), 0.5);
  EXPECT_NE(why.find("the two ceiling sides are 25% apart"), std::string::npos) << why;
  EXPECT_NE(why.find("two layouts fit"), std::string::npos) << why;
}

}  // namespace
}  // namespace corridor
