// FrameConfidence: the product of its factors and the weakest one's reason, against values
// computed by hand from the rules in docs/method.md ("Frame confidence").
#include "pipeline/frame_confidence.h"

#include <cmath>

#include <gtest/gtest.h>

namespace corridor {
namespace {

TEST(FrameConfidenceTest, GoodEvidenceIsOneAndSaysSo) {
  FrameEvidence e;
  e.junction[0] = e.junction[1] = 0.5;  // Both past the ramp: factors of 1.
  std::string why;
  EXPECT_DOUBLE_EQ(FrameConfidence(e, &why), 1.0);
  EXPECT_EQ(why, "the evidence is good");
}

TEST(FrameConfidenceTest, TheWeakestFactorGivesTheReason) {
  FrameEvidence e;
  e.junction[0] = 0.09;  // 0.6 + 0.4 * (0.09 - 0.03) / 0.12 = 0.8.
  e.junction[1] = 0.5;   // 1.
  e.crossings[1].reaching = 4;
  e.crossings[1].crossing = 3;  // 3 / 5 = 0.6: 1 - 0.8 * (0.6 - 0.35) / 0.4 = 0.5.
  e.corrected = true;           // 0.9.
  std::string why;
  EXPECT_NEAR(FrameConfidence(e, &why), 0.8 * 0.5 * 0.9, 1e-12);
  EXPECT_EQ(why,
            "vertical edges cross the right junction (3 of 4): the wall goes on below it (a rail, "
            "sill or bench edge taken for the floor's edge?)");
  // Without a place for the reason, the same confidence.
  EXPECT_NEAR(FrameConfidence(e), 0.8 * 0.5 * 0.9, 1e-12);
  // The ceiling's disagreement weakest: log(1.25), 25% -> 1 - 0.4 * (0.223 - 0.1) / 0.2.
  e.crossings[1] = VerticalCrossings();
  e.junction[0] = 0.5;
  e.ceiling_disagreement = std::log(1.25);
  EXPECT_NEAR(FrameConfidence(e, &why), (1.0 - 0.4 * (std::log(1.25) - 0.1) / 0.2) * 0.9, 1e-12);
  EXPECT_EQ(why, "the two ceiling sides disagree by 25%: a junction is not the floor's edge");
}

TEST(FrameConfidenceTest, AJunctionWithNoEdgeSupportIsRefusedUnlessTheCeilingConfirmsIt) {
  FrameEvidence e;
  e.junction[0] = 0.01;  // Under the ramp's start (0.03).
  e.junction[1] = 0.5;
  std::string why;
  // No ceiling compared: 0.5 on its own, under the default bar of 0.6.
  EXPECT_DOUBLE_EQ(FrameConfidence(e, &why), 0.5);
  EXPECT_EQ(why,
            "the left junction line has little edge support (0.01) and no ceiling confirms "
            "its wall");
  // Ceiling sides 20% apart do not confirm it either.
  e.ceiling_disagreement = std::log(1.2);
  EXPECT_NEAR(FrameConfidence(e), 0.5 * (1.0 - 0.4 * (std::log(1.2) - 0.1) / 0.2), 1e-12);
  // Sides 2% apart (within 6%) confirm both walls: the ramp's floor of 0.6, and the ceiling's
  // factor of 1 (under 0.1).
  e.ceiling_disagreement = std::log(1.02);
  EXPECT_DOUBLE_EQ(FrameConfidence(e, &why), 0.6);
  EXPECT_EQ(why, "the left junction line has little edge support (0.01)");
  // From the ramp's start on, the ramp: 0.03 gives 0.6 without a ceiling.
  e.ceiling_disagreement = -1;
  e.junction[0] = 0.03;
  EXPECT_DOUBLE_EQ(FrameConfidence(e), 0.6);
}

}  // namespace
}  // namespace corridor
