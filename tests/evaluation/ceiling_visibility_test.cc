#include "evaluation/ceiling_visibility.h"

#include <cmath>

#include <gtest/gtest.h>

#include "synth/presets.h"
#include "tests/support/camera_expect.h"

namespace corridor {
namespace {

// The paper's camera, whose intrinsics the hand computations below use: 420x360, fx = fy = 250,
// principal point (209.5, 179.5), no distortion.
Camera PaperCamera() {
  const Camera camera = synth::PaperCamera(0.66);
  testing_util::ExpectPinhole(camera, 420, 360, 250.0, 250.0, 209.5, 179.5);
  EXPECT_FALSE(camera.HasDistortion());
  return camera;
}

// Level camera on the axis of a 2 m corridor: the left ceiling junction (-1, h - H, Z) projects
// to u = cx - fx / Z, v = cy + fy (h - H) / Z, a straight line in s = 1/Z.
CorridorGeometry LevelCorridor(double ceiling_height) {
  CorridorGeometry g;
  g.width = 2.0;
  g.camera_height = 0.66;
  g.ceiling_height = ceiling_height;
  return g;
}

// By hand: with H - h = 2, the point is in the image while v >= 0, s <= 179.5 / 500, and
// u >= 0, s <= 209.5 / 250 (the weaker bound); from s = 1/40 (max_depth) up to 0.359 the
// image point moves |(fx, 2 fy)| = 559.02 px per unit of s.
TEST(CeilingVisibilityTest, VisibleLengthMatchesTheHandComputedProjection) {
  const Camera camera = PaperCamera();
  const double per_s = std::hypot(250.0, 500.0);
  const double expected = per_s * (179.5 / 500.0 - 1.0 / 40.0);
  EXPECT_NEAR(VisibleCeilingJunctionLength(LevelCorridor(2.66), camera, -1), expected, 1.0);
  // The right wall is the mirror image about cx: the same length.
  EXPECT_NEAR(VisibleCeilingJunctionLength(LevelCorridor(2.66), camera, +1), expected, 1.0);
  EXPECT_TRUE(CeilingJunctionVisible(LevelCorridor(2.66), camera));
}

TEST(CeilingVisibilityTest, AnEndWallCutsTheJunctionShort) {
  const Camera camera = PaperCamera();
  CorridorGeometry g = LevelCorridor(2.66);
  g.end_distance = 5.0;  // s from 1/5 instead of 1/40.
  const double expected = std::hypot(250.0, 500.0) * (179.5 / 500.0 - 1.0 / 5.0);
  EXPECT_NEAR(VisibleCeilingJunctionLength(g, camera, -1), expected, 1.0);
}

// H - h = 40: v >= 0 needs s <= 179.5 / 10000 < 1/40, so no point within 40 m is in the image.
TEST(CeilingVisibilityTest, ACeilingAboveTheViewIsNotVisible) {
  const Camera camera = PaperCamera();
  EXPECT_EQ(VisibleCeilingJunctionLength(LevelCorridor(40.66), camera, -1), 0.0);
  EXPECT_FALSE(CeilingJunctionVisible(LevelCorridor(40.66), camera));
}

// A ceiling only just in view: H - h = 26.5 leaves s in [1/40, 179.5 / 6625], about 14 px of
// junction, under 10% of the image's 360 px.
TEST(CeilingVisibilityTest, AShortGlimpseDoesNotCount) {
  const Camera camera = PaperCamera();
  const double a = 26.5;
  const double expected = std::hypot(250.0, 250.0 * a) * (179.5 / (250.0 * a) - 1.0 / 40.0);
  const CorridorGeometry g = LevelCorridor(0.66 + a);
  EXPECT_NEAR(VisibleCeilingJunctionLength(g, camera, -1), expected, 1.0);
  EXPECT_FALSE(CeilingJunctionVisible(g, camera));
}

TEST(CeilingVisibilityTest, NoCeilingOrBadGeometryIsNotVisible) {
  const Camera camera = PaperCamera();
  EXPECT_FALSE(CeilingJunctionVisible(LevelCorridor(0.0), camera));  // Unknown ceiling.
  CorridorGeometry g = LevelCorridor(2.66);
  g.yaw = std::nan("");
  EXPECT_EQ(VisibleCeilingJunctionLength(g, camera, -1), 0.0);
}

}  // namespace
}  // namespace corridor
