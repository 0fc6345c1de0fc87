// Frames of the real-buildings preset's mix class whose first layout puts a wall on a line with no
// floor below it (the grey wall under a window band, a wainscot's lower edge): more than 10% off,
// with that junction's confidence under 0.03 and no ceiling sides compared. By default they are
// refused, saying why. A frame whose weak junction the ceiling confirms (a runner hides the floor's
// colour at the bottom of the image, so the true junction scores nothing against it) is kept,
// within 3% of the true width. Truth is the generator's.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

using testing_util::ExpectOffThenRefused;
using testing_util::PresetFrame;
using testing_util::RenderPreset;

struct Case {
  const char* name;
  int scene, index;
};

double WeakestJunction(const RecoverDepthResult& r) {
  return std::min(r.evidence.junction[0], r.evidence.junction[1]);
}

TEST(WeakJunctionTest, AWallOnALineThatBoundsNoFloorIsRefused) {
  for (const Case& c : {Case{"mix", 9, 2}, Case{"mix", 7, 8}}) {
    const PresetFrame f = RenderPreset(c.name, c.scene, c.index);
    const std::string label =
        std::string(c.name) + " " + std::to_string(c.scene) + " " + std::to_string(c.index);
    ASSERT_FALSE(f.frame.bgr.empty()) << label;
    const RecoverDepthResult result =
        ExpectOffThenRefused(f, 0.10, "no ceiling confirms its wall", label);
    EXPECT_LT(WeakestJunction(result), 0.03) << label;
    EXPECT_LT(result.evidence.ceiling_disagreement, 0) << label;
  }
}

TEST(WeakJunctionTest, AWeakJunctionTheCeilingConfirmsIsKept) {
  const PresetFrame f = RenderPreset("floor", 0, 14);
  ASSERT_FALSE(f.frame.bgr.empty());
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &result).ok())
      << result.status.ToString();
  EXPECT_LT(WeakestJunction(result), 0.03);
  EXPECT_GE(result.evidence.ceiling_disagreement, 0);
  EXPECT_LT(result.evidence.ceiling_disagreement, std::log(1.06));
  EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03);
}

}  // namespace
}  // namespace corridor
