// The inner-line check moves a wall only where the image shows its new junction, and moves a wall
// in only as far as a baseboard's top explains. Frames of the generator's real-buildings preset
// (the same scenes and poses corridor_synth renders), truth from the generator's scene: each guard
// keeps a frame right that the check without it puts wrong.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/real_buildings.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

using testing_util::PresetFrame;

PresetFrame Render(const std::string& class_name, int scene, int index) {
  return testing_util::RenderPreset(class_name, scene, index);
}

using testing_util::RecoveredWidthError;

// A window band on one wall: its top is read as that side's ceiling junction, far too high, so the
// two ceiling sides disagree and the check would move the other, correct, wall out several times
// its distance, onto the plain face of a wall that is not there. No edge follows the junction
// there: the wall stays.
TEST(InnerLineGuardTest, AWindowBandDoesNotMoveTheCorrectWallOut) {
  for (const int index : {0, 1}) {
    const PresetFrame f = Render("windows", 2, index);
    ASSERT_FALSE(f.frame.bgr.empty());
    RecoverDepthOptions options;
    EXPECT_LT(RecoveredWidthError(f, options), 0.03) << index;
    options.inner_line.min_target_support = 0;
    options.max_width = 20;  // The moved wall reported, not refused as wider than a corridor.
    EXPECT_GT(RecoveredWidthError(f, options), 0.5) << index;
    options.max_width = RecoverDepthOptions().max_width;
    EXPECT_TRUE(std::isnan(RecoveredWidthError(f, options))) << index;
  }
}

// A head-mounted camera (about 1.6 m high): the check would move a wall in by 0.82, as a baseboard
// top 0.3 m above the floor would explain. Either guard keeps the wall: such a baseboard is
// taller than any, and no edge follows the junction where the wall would go. The frame is
// recovered as seen (its roll left in), where the check meets that wall.
TEST(InnerLineGuardTest, AHighCameraDoesNotMoveAWallInFurtherThanABaseboardExplains) {
  const PresetFrame f = Render("head", 4, 8);
  ASSERT_FALSE(f.frame.bgr.empty());
  RecoverDepthOptions options;
  options.level_roll = false;
  EXPECT_LT(RecoveredWidthError(f, options), 0.03);
  options.inner_line.min_target_support = 0;
  EXPECT_LT(RecoveredWidthError(f, options), 0.03);
  options.inner_line.max_baseboard_height = 0;
  EXPECT_GT(RecoveredWidthError(f, options), 0.08);
  options.inner_line.min_target_support = InnerLineCheckOptions().min_target_support;
  EXPECT_LT(RecoveredWidthError(f, options), 0.03);
}

TEST(InnerLineGuardTest, BadOptionsAreRejected) {
  for (const double bad : {-0.1, 1.5, std::nan("")}) {
    InnerLineCheckOptions options;
    options.min_target_support = bad;
    std::string why;
    EXPECT_FALSE(options.Check(&why)) << bad;
    EXPECT_NE(why.find("min_target_support"), std::string::npos) << why;
  }
  for (const double bad : {-0.1, std::nan("")}) {
    InnerLineCheckOptions options;
    options.max_baseboard_height = bad;
    std::string why;
    EXPECT_FALSE(options.Check(&why)) << bad;
    EXPECT_NE(why.find("max_baseboard_height"), std::string::npos) << why;
  }
  for (const double bad : {-1.0, std::nan("")}) {
    InnerLineCheckOptions options;
    options.far_max_height = bad;
    std::string why;
    EXPECT_FALSE(options.Check(&why)) << bad;
    EXPECT_NE(why.find("far_max_height"), std::string::npos) << why;
  }
  for (const double bad : {0.0, 1.5, std::nan("")}) {
    InnerLineCheckOptions options;
    options.min_far_ceiling_support = bad;
    std::string why;
    EXPECT_FALSE(options.Check(&why)) << bad;
    EXPECT_NE(why.find("min_far_ceiling_support"), std::string::npos) << why;
  }
  InnerLineCheckOptions far_off;
  far_off.far_max_height = 0;
  EXPECT_TRUE(far_off.Check(nullptr));
}

}  // namespace
}  // namespace corridor
