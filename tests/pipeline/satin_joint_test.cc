// A tile joint on a satin floor, end to end (the reflecting-floor class's scene 0): the joint
// nearest each wall runs about 0.15 m from it, with the baseboard's faint reflection between, so
// the strip beyond the joint is only 0.91-0.94 alike to the floor. The inside-floor rule's relaxed
// likeness for a ridge takes the junctions beyond the joints; without it both walls come out about
// 15% too near. The same at twice the resolution, where the working scale doubles every probe
// (frame 10 is not asserted there: its right wall's line is taken back down by the pipeline's
// baseboard-foot check after the rule).
// Truth from the generator's ray caster.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

using testing_util::RecoveredWidthError;

void ExpectTheJointsAreStepped(int width_px, int height_px, std::initializer_list<int> frames) {
  for (const int index : frames) {
    const testing_util::PresetFrame f =
        testing_util::RenderPreset("satin", 0, index, width_px, height_px);
    ASSERT_FALSE(f.frame.bgr.empty());
    RecoverDepthOptions options;
    const double with_rule = RecoveredWidthError(f, options);
    options.perception.inside_floor_ridge_likeness = 0;
    const double without = RecoveredWidthError(f, options);
    std::printf("satin scene 0 frame %d at %dx%d: width %.1f%% off, %.1f%% without the ridge\n",
                index, width_px, height_px, 100 * with_rule, 100 * without);
    EXPECT_LT(with_rule, 0.03) << index;
    EXPECT_GT(without, 0.1) << index;
  }
}

TEST(SatinJointTest, TheJunctionsBeyondTheJointsAreTaken) {
  ExpectTheJointsAreStepped(640, 480, {0, 2, 4});
}

TEST(SatinJointTest, TheJunctionsBeyondTheJointsAreTakenAtTwiceTheResolution) {
  ExpectTheJointsAreStepped(1280, 960, {0, 4});
}

}  // namespace
}  // namespace corridor
