// The baseboard-feet check (pipeline/baseboard_feet.h): both junctions on their baseboards' tops
// put both walls too far by h / (h - b); the bands' feet move them back, at one baseboard height.
// Junctions on the floor's edge stay, on a plain floor and on a polished one whose reflection of
// the baseboard makes a band of the same kind below them. Truth from the generator: its frames,
// their geometry, and the baseboard heights set in its scenes.
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "perception/working_image.h"
#include "pipeline/baseboard_feet.h"
#include "pipeline/chosen_solve.h"
#include "synth/corridor_renderer.h"
#include "synth/corridor_scene.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

struct FeetCase {
  synth::Frame frame;
  Camera camera;
};

// A corridor 2.2 m wide with a baseboard `height` m high, 0.7 darker than the wall, and a floor
// that mirrors `gloss` of what it faces; no doors; the camera 0.66 m high, offset and turned.
FeetCase Render(double height, double gloss) {
  synth::SceneOptions options;
  options.width = 2.2;
  options.ceiling_height = 2.7;
  options.clutter = 0;
  options.door_density = 0;
  options.baseboard_height = height;
  options.baseboard_contrast = 0.7;
  options.floor_gloss = gloss;
  options.seed = 11;
  FeetCase c;
  c.camera = synth::PaperCamera(0.66);
  EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(options), c.camera,
                                 synth::CameraPose{0.05, 0.03, 0.15, 0.66, 4.0}, &c.frame)
                  .ok());
  return c;
}

// The junction line of `g`'s wall on `side` (< 0: left), its ends the projections at 3 and 15 m
// ahead (by hand, as TrueJunction's).
JunctionLine LineOf(const CorridorGeometry& g, const Camera& camera, int side) {
  JunctionLine line;
  line.line = testing_util::TrueJunction(g, camera, side);
  const double x = side < 0 ? -(g.width / 2 + g.offset) : g.width / 2 - g.offset;
  const Eigen::Vector2d ends[2] = {testing_util::ProjectFloorPoint(g, camera, x, 3.0),
                                   testing_util::ProjectFloorPoint(g, camera, x, 15.0)};
  line.near_end = ends[0];
  line.far_end = ends[1];
  line.support_length = (ends[0] - ends[1]).norm();
  line.confidence = 1;
  return line;
}

using FeetCheck = BaseboardFeet (*)(const WallCheckInputs&, const BaseboardFeetOptions&,
                                    CorridorGeometry*, RecoverDepthResult*);

// The check `check` on junctions drawn where the walls of `g` put them (no ceiling found).
BaseboardFeet Check(const FeetCase& c, const BaseboardFeetOptions& feet_options,
                    CorridorGeometry* g, RecoverDepthResult* result,
                    FeetCheck check = TakeBothBaseboardFeet) {
  const RecoverDepthOptions options = LayoutOptions(RecoverDepthOptions());
  std::unique_ptr<CorridorSolver> solver;
  EXPECT_TRUE(CreateSolver(LayoutSolverName(), options.solver_options, &solver).ok());
  const WorkingImage search = HalveToWidth(c.frame.bgr, c.camera, options.search_max_width);
  ImageEdges edges;
  const WallCheckInputs in{options, *solver, c.camera, search, &edges};
  result->junctions.status = Status::Ok();
  result->junctions.left = LineOf(*g, c.camera, -1);
  result->junctions.right = LineOf(*g, c.camera, 1);
  const Eigen::Vector3d vp = result->junctions.left.line.cross(result->junctions.right.line);
  result->junctions.vanishing_point = vp.head<2>() / vp.z();
  return check(in, feet_options, g, result);
}

// Both walls put where the baseboard's top says: h / (h - b) too far.
CorridorGeometry OnTheTops(const CorridorGeometry& truth, double height) {
  const double r = truth.camera_height / (truth.camera_height - height);
  CorridorGeometry g = truth;
  g.SetWallDistances(r * truth.LeftDistance(), r * truth.RightDistance());
  return g;
}

TEST(BaseboardFeetTest, BothWallsOnTheTopsMoveToTheFeet) {
  for (const double height : {0.08, 0.1, 0.12}) {
    const FeetCase c = Render(height, 0.0);
    ASSERT_FALSE(c.frame.bgr.empty());
    const CorridorGeometry& truth = c.frame.truth;
    CorridorGeometry g = OnTheTops(truth, height);
    RecoverDepthResult result;
    const BaseboardFeet feet = Check(c, BaseboardFeetOptions(), &g, &result);
    EXPECT_TRUE(feet.taken) << height << ": ratios " << feet.ratio[0] << ", " << feet.ratio[1];
    if (!feet.taken) continue;
    EXPECT_NEAR(g.LeftDistance(), truth.LeftDistance(), 0.02 * truth.LeftDistance()) << height;
    EXPECT_NEAR(g.RightDistance(), truth.RightDistance(), 0.02 * truth.RightDistance()) << height;
    // The ratio gives back the baseboard's height.
    const double r = std::sqrt(feet.ratio[0] * feet.ratio[1]);
    EXPECT_NEAR(truth.camera_height * (1 - 1 / r), height, 0.01) << height;
    EXPECT_NE(result.fallback.find("feet of the bands"), std::string::npos) << result.fallback;
  }
}

// Both the two-wall and the one-wall (other wall's band) checks.
TEST(BaseboardFeetTest, JunctionsOnTheFloorsEdgeStay) {
  for (const double gloss : {0.0, 0.5}) {
    const FeetCase c = Render(0.1, gloss);
    ASSERT_FALSE(c.frame.bgr.empty());
    for (const FeetCheck check : {TakeBothBaseboardFeet, TakeFootShownAcross}) {
      CorridorGeometry g = c.frame.truth;
      RecoverDepthResult result;
      EXPECT_FALSE(Check(c, BaseboardFeetOptions(), &g, &result, check).taken)
          << "gloss " << gloss;
      EXPECT_EQ(g.width, c.frame.truth.width);
      EXPECT_EQ(g.offset, c.frame.truth.offset);
    }
  }
}

// On the polished floor it is the baseboard's top above the junctions that tells: without that
// test the reflection's foot would be taken, both walls in by (h + b) / h. The one-wall check,
// whose other wall shows a baseboard's top at the band's height, is told by the same top above the
// wall that would move (max_above_support): blind to it, that wall goes (h + b) / h in.
TEST(BaseboardFeetTest, AReflectionIsToldByTheBaseboardsTopAbove) {
  const FeetCase c = Render(0.1, 0.5);
  ASSERT_FALSE(c.frame.bgr.empty());
  const double reflected = (0.66 + 0.1) / 0.66;
  BaseboardFeetOptions no_mirror_test;
  no_mirror_test.max_mirror_support = 1;
  CorridorGeometry g = c.frame.truth;
  RecoverDepthResult result;
  BaseboardFeet feet = Check(c, no_mirror_test, &g, &result);
  ASSERT_TRUE(feet.taken);
  EXPECT_NEAR(feet.ratio[0], reflected, 0.03 * reflected);
  EXPECT_NEAR(feet.ratio[1], reflected, 0.03 * reflected);
  g = c.frame.truth;
  EXPECT_FALSE(Check(c, no_mirror_test, &g, &result, TakeFootShownAcross).taken);
  BaseboardFeetOptions blind = no_mirror_test;
  blind.max_above_support = 0.999;
  feet = Check(c, blind, &g, &result, TakeFootShownAcross);
  ASSERT_TRUE(feet.taken);
  EXPECT_NEAR(std::max(feet.ratio[0], feet.ratio[1]), reflected, 0.03 * reflected);
}

// A satin floor below a baseboard of nearly the wall's colour (the satin class's scene 0, frame
// 18): no top stands above the junctions, and the reflection makes a band below each, of one
// ratio; it fades into the floor, where a baseboard is one colour top to foot. Without the fade
// test both walls would go 14% too near.
TEST(BaseboardFeetTest, ASatinFloorsFadingReflectionIsNotABaseboard) {
  const testing_util::PresetFrame f = testing_util::RenderPreset("satin", 0, 18);
  RecoverDepthOptions options;
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok());
  EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03);
  EXPECT_EQ(result.fallback.find("feet of the bands"), std::string::npos) << result.fallback;
  options.baseboard_feet.max_band_fade = 1e9;
  ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok());
  EXPECT_NE(result.fallback.find("feet of the bands"), std::string::npos) << result.fallback;
  EXPECT_GT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.1);
}

// One wall on its baseboard's top, no ceiling found: the other wall shows the band's top at the
// height the foot gives, and the wall moved has none above its line first taken.
TEST(BaseboardFeetTest, OneWallOnItsTopMovesToItsFootWhenTheOtherShowsTheBand) {
  for (const int side : {0, 1}) {
    const FeetCase c = Render(0.1, 0.0);
    ASSERT_FALSE(c.frame.bgr.empty());
    const CorridorGeometry& truth = c.frame.truth;
    const double r = truth.camera_height / (truth.camera_height - 0.1);
    CorridorGeometry g = truth;
    g.SetWallDistances(side == 0 ? r * truth.LeftDistance() : truth.LeftDistance(),
                       side == 1 ? r * truth.RightDistance() : truth.RightDistance());
    RecoverDepthResult result;
    const BaseboardFeet feet =
        Check(c, BaseboardFeetOptions(), &g, &result, TakeFootShownAcross);
    ASSERT_TRUE(feet.taken) << side;
    EXPECT_NEAR(feet.ratio[side], r, 0.02 * r) << side;
    EXPECT_NEAR(g.LeftDistance(), truth.LeftDistance(), 0.02 * truth.LeftDistance()) << side;
    EXPECT_NEAR(g.RightDistance(), truth.RightDistance(), 0.02 * truth.RightDistance()) << side;
    EXPECT_NE(result.fallback.find("the other wall shows"), std::string::npos) << result.fallback;
    // Off, or with the band's top asked for where the other wall has none, nothing moves.
    BaseboardFeetOptions off;
    off.min_across_support = 0;
    g = CorridorGeometry(truth);
    g.SetWallDistances(side == 0 ? r * truth.LeftDistance() : truth.LeftDistance(),
                       side == 1 ? r * truth.RightDistance() : truth.RightDistance());
    const double before = g.width;
    EXPECT_FALSE(Check(c, off, &g, &result, TakeFootShownAcross).taken);
    EXPECT_EQ(g.width, before);
  }
}

TEST(BaseboardFeetTest, OffMovesNothing) {
  const FeetCase c = Render(0.1, 0.0);
  ASSERT_FALSE(c.frame.bgr.empty());
  CorridorGeometry g = OnTheTops(c.frame.truth, 0.1);
  const CorridorGeometry before = g;
  BaseboardFeetOptions off;
  off.same_ratio = 0;
  RecoverDepthResult result;
  EXPECT_FALSE(Check(c, off, &g, &result).taken);
  EXPECT_EQ(g.width, before.width);
}

TEST(BaseboardFeetTest, OptionsAreChecked) {
  EXPECT_TRUE(BaseboardFeetOptions().Check(nullptr));
  const auto rejects = [](BaseboardFeetOptions o, const char* name) {
    std::string why;
    EXPECT_FALSE(o.Check(&why)) << name;
    EXPECT_NE(why.find(name), std::string::npos) << why;
  };
  BaseboardFeetOptions o;
  o.same_ratio = -0.1;
  rejects(o, "same_ratio");
  o = BaseboardFeetOptions();
  o.ceiling_ratio = 1;
  rejects(o, "ceiling_ratio");
  o = BaseboardFeetOptions();
  o.max_height = o.min_height;
  rejects(o, "max_height");
  o = BaseboardFeetOptions();
  o.min_band_contrast = NAN;
  rejects(o, "min_band_contrast");
  o = BaseboardFeetOptions();
  o.max_band_fade = 0;
  rejects(o, "max_band_fade");
  o = BaseboardFeetOptions();
  o.max_mirror_support = 0;
  rejects(o, "max_mirror_support");
  o = BaseboardFeetOptions();
  o.min_across_support = -0.5;
  rejects(o, "min_across_support");
  o = BaseboardFeetOptions();
  o.max_above_support = 1;
  rejects(o, "max_above_support");
  RecoverDepthOptions options;
  options.baseboard_feet.min_height = 0;
  std::string why;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("baseboard_feet"), std::string::npos) << why;
}

// End to end on the real-buildings preset: the floor class's scenes 0 and 3, frame 2, whose two
// junctions were both taken on the baseboards' tops (17% too wide).
TEST(BaseboardFeetTest, EndToEndBothWallsComeBackToTheirFeet) {
  for (const int scene : {0, 3}) {
    const testing_util::PresetFrame f = testing_util::RenderPreset("floor", scene, 2);
    RecoverDepthResult result;
    ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &result).ok());
    EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03) << scene;
    EXPECT_TRUE(result.lower_line_taken) << scene;
  }
}

// One wall on its baseboard's top, end to end: its ceiling side is the higher by the ratio its
// band's foot moves it in by. The baseboard class's scene 7 frame 11 (the right wall on a line
// above its foot, 6.5% wide), the rail class's scene 6 frame 13 (the left, 8.3% wide) and the
// glossy class's scene 1 frame 14 (the left, 5.8% wide). With both one-wall checks off (the rail
// frame's other wall shows the band's top too), they stay more than 5% off.
TEST(BaseboardFeetTest, EndToEndOneWallComesBackToItsFoot) {
  for (const auto& [name, scene, frame] :
       {std::tuple<const char*, int, int>{"baseboard", 7, 11}, {"rail", 6, 13}, {"glossy", 1, 14}}) {
    const testing_util::PresetFrame f = testing_util::RenderPreset(name, scene, frame);
    RecoverDepthOptions options;
    RecoverDepthResult result;
    ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok()) << name;
    EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03) << name;
    EXPECT_NE(result.fallback.find("as its ceiling side's height over the other's"),
              std::string::npos)
        << name << ": " << result.fallback;
    options.baseboard_feet.ceiling_ratio = 0;
    options.baseboard_feet.min_across_support = 0;
    ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok()) << name;
    EXPECT_GT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.05) << name;
  }
}

// One wall on its baseboard's top where the ceiling does not tell, end to end: the pillars
// class's scene 3 frames 4 and 13 (a grey baseboard on a dark tiled floor, the right wall 9-11%
// too far) and scene 5 frame 13, and the carpet class's scene 4 frame 17 (the right wall, 11%).
// Off, they stay more than 5% off.
TEST(BaseboardFeetTest, EndToEndTheOtherWallsBandBringsOneWallToItsFoot) {
  for (const auto& [name, scene, frame] : {std::tuple<const char*, int, int>{"pillars", 3, 4},
                                           {"pillars", 3, 13},
                                           {"pillars", 5, 13},
                                           {"carpet", 4, 17}}) {
    const testing_util::PresetFrame f = testing_util::RenderPreset(name, scene, frame);
    RecoverDepthOptions options;
    RecoverDepthResult result;
    ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok()) << name;
    EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03)
        << name << " " << scene << " " << frame;
    EXPECT_NE(result.fallback.find("the other wall shows"), std::string::npos)
        << name << ": " << result.fallback;
    options.baseboard_feet.min_across_support = 0;
    ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok()) << name;
    EXPECT_GT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.05)
        << name << " " << scene << " " << frame;
  }
}

// Where the ceiling sides are found but read off other lines (the mix class's scene 8 frame 15:
// they disagree by 37%, far from the band's ratio, so TakeOneBaseboardFoot takes nothing), the
// other wall's band still brings the left wall to its foot; off, the frame is refused.
TEST(BaseboardFeetTest, EndToEndTheOtherWallsBandWhereTheCeilingSidesDisagree) {
  const testing_util::PresetFrame f = testing_util::RenderPreset("mix", 8, 15);
  RecoverDepthOptions options;
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok()) << result.fallback;
  EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03);
  EXPECT_NE(result.fallback.find("the other wall shows"), std::string::npos) << result.fallback;
  options.baseboard_feet.min_across_support = 0;
  EXPECT_EQ(RecoverDepth(f.frame.bgr, f.camera, options, &result).code(),
            StatusCode::kLowConfidence);
  EXPECT_NE(result.status.message().find("ceiling sides disagree"), std::string::npos)
      << result.status.message();
}

}  // namespace
}  // namespace corridor
