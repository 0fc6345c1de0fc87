// JunctionPair::at_reflected_band on the polished-floor class (glossy): a side flagged as standing
// at a baseboard-and-reflection band's middle has its junction on the true floor/wall junction
// (the baseboard's foot is that band's middle), within 2 px along its extent. Truth from the
// generator's ray caster, the junction projected by hand (TrueJunction).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "tests/support/corridor_frame.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

TEST(ReflectedBandFlagTest, AFlaggedJunctionIsOnTheBaseboardsFoot) {
  int flagged = 0;
  for (const int index : {0, 5, 10, 15}) {
    const testing_util::PresetFrame f = testing_util::RenderPreset("glossy", 0, index);
    ASSERT_FALSE(f.frame.bgr.empty());
    RecoverDepthResult result;
    RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &result);
    if (!result.junctions.status.ok()) continue;
    const JunctionLine* lines[2] = {&result.junctions.left, &result.junctions.right};
    for (int side = 0; side < 2; ++side) {
      if (!result.junctions.at_reflected_band[side]) continue;
      ++flagged;
      const Eigen::Vector3d truth =
          testing_util::TrueJunction(f.frame.truth, f.camera, side == 0 ? -1 : 1);
      for (const Eigen::Vector2d& end : {lines[side]->near_end, lines[side]->far_end}) {
        const double off = std::abs(truth.dot(end.homogeneous()));
        std::printf("frame %d side %d: %.2f px from the true junction\n", index, side, off);
        EXPECT_LT(off, 2.0) << index << " " << side;
      }
    }
  }
  // The premise: the class's frames do stand at such bands.
  EXPECT_GT(flagged, 0);
}

}  // namespace
}  // namespace corridor
