// The floor rule's texture test on a faint carpet, end to end: a runner with a yellow border on a
// carpeted floor, seen from a head-mounted camera (the mix class's scene 7). The carpet between
// the border and each wall shows 2-3 edge pixels per hundred band pixels, mostly oblique. Asked
// for 5 per hundred (floor_band_texture_density 0.05), the texture test leaves the runner's edges
// taken and the width comes out about 40% short; at the default 0.02 the junctions beyond the
// carpet are taken. Truth from the generator's ray caster.
#include <cmath>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

using testing_util::RecoveredWidthError;

TEST(FaintCarpetTest, TheJunctionsBeyondARunnerOnFaintCarpetAreTaken) {
  for (const int index : {0, 3}) {
    const testing_util::PresetFrame f = testing_util::RenderPreset("mix", 7, index);
    ASSERT_FALSE(f.frame.bgr.empty());
    RecoverDepthOptions options;
    EXPECT_LT(RecoveredWidthError(f, options), 0.03) << index;
    options.perception.floor_band_texture_density = 0.05;
    EXPECT_GT(RecoveredWidthError(f, options), 0.3) << index;
  }
}

}  // namespace
}  // namespace corridor
