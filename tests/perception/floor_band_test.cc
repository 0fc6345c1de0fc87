// The floor and stripe rules' measures: MeasureBandEdges on edge pixels placed by hand (which
// class each falls in is worked out here from its gradient and position), SampleBelowLine and
// FloorLikenessAbove on a two-colour image, and the rules on generated corridors with a carpet
// runner or floor stripes, against the generator's junction lines.
#include "perception/floor_band.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "perception/appearance.h"
#include "perception/junction_detector.h"
#include "tests/support/image_line.h"
#include "synth/corridor_renderer.h"
#include "synth/real_buildings.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

using testing_util::DownLine;

struct EdgeMaps {
  cv::Mat edges, dx, dy;
  explicit EdgeMaps(cv::Size size)
      : edges(cv::Mat::zeros(size, CV_8U)),
        dx(cv::Mat::zeros(size, CV_16S)),
        dy(cv::Mat::zeros(size, CV_16S)) {}
  // An edge pixel at (u, v) with gradient (gx, gy); `on` false: the gradient only (no edge).
  void Put(int u, int v, double gx, double gy, bool on = true) {
    edges.at<uchar>(v, u) = on ? 255 : 0;
    dx.at<short>(v, u) = static_cast<short>(std::lround(gx));
    dy.at<short>(v, u) = static_cast<short>(std::lround(gy));
  }
};

// A left wall's band, the vanishing point at (150, 20): the inner line (a runner's edge) reaches
// (30, 200), the outer one (the junction) (0, 120). At row 150 the inner line is at u = 63.3 and
// the outer at u = -45: the band spans the row's first 60 pixels.
class BandTest : public ::testing::Test {
 protected:
  const Eigen::Vector2d vp{150, 20};
  const Eigen::Vector3d inner = DownLine(vp, {30, 200});
  const Eigen::Vector3d outer = DownLine(vp, {0, 120});
  EdgeMaps maps{cv::Size(300, 200)};
  BandEdges Measure() const {
    return MeasureBandEdges(maps.edges, maps.dx, maps.dy, GradientGrid(), inner, outer, vp,
                            BandEdgeOptions());
  }
};

TEST_F(BandTest, CountsAcrossAndVerticalEdges) {
  // Row 150: the band spans u in [0, 60); row 140: [0, 66).
  maps.Put(50, 150, 0, 200);         // Horizontal edge: across.
  maps.Put(48, 150, 10, -150);       // 3.8 deg from horizontal: across.
  maps.Put(5, 150, 0, -200);         // Across.
  maps.Put(7, 150, 300, 20);         // 3.8 deg from vertical: vertical.
  maps.Put(50, 140, -200, 0);        // Vertical.
  maps.Put(40, 140, 0, 200);         // Across, on a second row.
  maps.Put(30, 150, 150, 150);       // 45 degrees: neither; it runs toward the vanishing point.
  maps.Put(20, 150, 100, 35);        // 19 deg from vertical, not toward it: oblique.
  maps.Put(31, 150, 0, 200, false);  // A gradient without an edge pixel.
  const BandEdges band = Measure();
  EXPECT_EQ(band.across, 4);
  EXPECT_EQ(band.across_rows, 2);
  EXPECT_EQ(band.vertical, 2);
  // (30, 150) runs along (-1, 1), 2.3 deg from the direction (120, -130) to the vanishing point
  // (within 10); (20, 150) along (-35, 100), 23 deg from it.
  EXPECT_EQ(band.oblique, 1);
}

TEST_F(BandTest, IgnoresPixelsOutsideTheBand) {
  maps.Put(100, 150, 0, 200);  // Below the inner line (on the runner): u = 100 > 63.3.
  maps.Put(62, 150, 0, 200);   // Within the 3 px margin of the inner line.
  maps.Put(160, 21, 0, 200);   // Right of the vanishing point, hardly below its row.
  maps.Put(10, 60, 0, 200);    // Above the outer line (on the wall): its row at u = 10 is 113.
  ASSERT_GT(20 + (150 - 10) * (100.0 / 150.0), 60.0);
  const BandEdges band = Measure();
  EXPECT_EQ(band.across, 0);
  EXPECT_EQ(band.vertical, 0);
}

TEST_F(BandTest, AnEdgeTowardTheVanishingPointIsNotAcross) {
  // Near the outer line far from the vanishing point the band's direction is 33.7 degrees from
  // horizontal; take a flatter pair of lines, 12 and 20 degrees, where an edge pointing at the
  // vanishing point is within 15 degrees of horizontal.
  const Eigen::Vector2d flat_vp(290, 20);
  const Eigen::Vector3d flat_inner = DownLine(flat_vp, {0, 20 + 290 * std::tan(20 * M_PI / 180)});
  const Eigen::Vector3d flat_outer = DownLine(flat_vp, {0, 20 + 290 * std::tan(12 * M_PI / 180)});
  // (40, 20 + 250 tan 16 deg): in the middle of the band; the direction to the vanishing point
  // is 16 degrees from horizontal; its gradient is normal to it.
  const double angle = 16 * M_PI / 180;
  const int v = static_cast<int>(std::lround(20 + 250 * std::tan(angle)));
  maps.Put(40, v, -200 * std::sin(angle), -200 * std::cos(angle));  // Edge toward the VP.
  maps.Put(44, v, 0, 200);                                          // A horizontal edge.
  const BandEdges band = MeasureBandEdges(maps.edges, maps.dx, maps.dy, GradientGrid(),
                                          flat_inner, flat_outer, flat_vp, BandEdgeOptions());
  EXPECT_EQ(band.across, 1);
  EXPECT_EQ(band.vertical, 0);
}

TEST_F(BandTest, ASteepEdgeTowardTheVanishingPointIsNotVertical) {
  // A steep band (a narrow view, a pitched camera): the inner line runs 4.5 degrees from
  // vertical to (120, 400), the outer one 13.3 degrees to (60, 400). At row 300 the band spans
  // u in (83.7, 127.9).
  EdgeMaps steep(cv::Size(300, 420));
  const Eigen::Vector3d steep_inner = DownLine(vp, {120, 400});
  const Eigen::Vector3d steep_outer = DownLine(vp, {60, 400});
  // (105, 300): the vanishing point lies along (45, -280), 9.1 degrees from vertical; an edge
  // along it (gradient (280, 45), 9.1 degrees from horizontal) runs along the corridor, though
  // within 15 degrees of vertical.
  steep.Put(105, 300, 280, 45);
  // (100, 310): an edge 5 degrees from vertical leaning the other way (gradient (cos 5, -sin 5)),
  // 14.8 degrees from the direction (50, -290) to the vanishing point: a door frame's.
  steep.Put(100, 310, 200 * std::cos(5 * M_PI / 180), -200 * std::sin(5 * M_PI / 180));
  const BandEdges band = MeasureBandEdges(steep.edges, steep.dx, steep.dy, GradientGrid(),
                                          steep_inner, steep_outer, vp, BandEdgeOptions());
  EXPECT_EQ(band.vertical, 1);
  EXPECT_EQ(band.across, 0);
  EXPECT_EQ(band.oblique, 0);
}

// Grey-blue above the line v = 0.5 u + 40, brown below it, and the line.
struct TwoColours {
  const cv::Vec3b above{180, 150, 140}, below{40, 90, 150};
  cv::Mat bgr = cv::Mat(200, 200, CV_8UC3);
  MergedLine line;
  TwoColours() {
    for (int v = 0; v < bgr.rows; ++v) {
      for (int u = 0; u < bgr.cols; ++u) {
        bgr.at<cv::Vec3b>(v, u) = v > 0.5 * u + 40 ? below : above;
      }
    }
    line.line = DownLine({0, 40}, {200, 140});
    line.start = {10, 45};
    line.end = {190, 135};
  }
};

// A colour's 8-bit Lab value, converted here pixel by pixel.
cv::Vec3f LabOf(const cv::Vec3b& c) {
  cv::Mat lab;
  cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar(c[0], c[1], c[2])), lab, cv::COLOR_BGR2Lab);
  return cv::Vec3f(lab.at<cv::Vec3b>(0, 0));
}

TEST(SampleBelowLineTest, GivesTheColourBelowTheLine) {
  const TwoColours image;
  const FloorAppearance floor = SampleBelowLine(image.bgr, image.line, 0, 1);
  const cv::Vec3f expected = LabOf(image.below);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(floor.lab[c], expected[c]) << "channel " << c;
  EXPECT_EQ(floor.spread, 1.0f);
}

TEST(FloorLikenessAboveTest, IsOneForTheFloorsColourAndTheGaussianOfItsDistanceElse) {
  const TwoColours image;
  const cv::Mat& bgr = image.bgr;
  const MergedLine& line = image.line;
  FloorAppearance brown, grey;
  brown.lab = LabOf(image.below);
  grey.lab = LabOf(image.above);
  // Uniform floors: spread 1, so the likeness is exp(-d^2 / (2 * 6^2)) with d the Lab distance
  // (lightness weighted a quarter: 0.0385 on the squared 8-bit L).
  const cv::Vec3f d = grey.lab - brown.lab;
  const double distance = std::sqrt(0.0385 * d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  ASSERT_GT(distance, 12.0);  // The premise: two clearly different colours.
  EXPECT_NEAR(FloorLikenessAbove(bgr, grey, line, 0, 1), 1.0, 1e-6);
  EXPECT_NEAR(FloorLikenessAbove(bgr, brown, line, 0, 1),
              std::exp(-distance * distance / (2 * 36.0)), 1e-6);
}

// Frame `index` of scene `scene` of a real-buildings class (`real_class`: "floor", "mix"), as the
// preset renders it, and the largest distance, px, of either found junction's support ends from
// the true line (the generator's scene projected by hand); NaN when no pair is found.
double WorstJunctionOffsetPx(const std::string& real_class, int scene, int index,
                             const JunctionDetectorOptions& options) {
  synth::RealBuildingsOptions preset_options;
  preset_options.scenes = scene + 1;
  preset_options.frames = index + 1;
  std::vector<synth::ScenePreset> presets;
  EXPECT_TRUE(synth::RealBuildingsPreset(real_class, preset_options, &presets).ok());
  const synth::ScenePreset& preset = presets.at(scene);
  synth::Frame frame;
  EXPECT_TRUE(synth::RenderFrame(preset.scene, preset.camera, preset.poses.at(index), &frame).ok());
  JunctionPair pair;
  EXPECT_TRUE(DetectJunctions(frame.bgr, options, &pair).ok());
  if (!pair.status.ok()) return std::nan("");
  double worst = 0;
  for (const int side : {-1, 1}) {
    const Eigen::Vector3d truth = testing_util::TrueJunction(frame.truth, preset.camera, side);
    const JunctionLine& found = side < 0 ? pair.left : pair.right;
    for (const Eigen::Vector2d& end : {found.near_end, found.far_end}) {
      worst = std::max(worst, std::abs(truth.dot(end.homogeneous())));
    }
  }
  return worst;
}

// On each (scene, frame) of `real_class`: the junctions found without a rule (`without`) lie more
// than `premise_px` from the true lines (the premise: a line inside the floor was taken), those
// found with the default options within `within_px`.
void ExpectTheRuleTakesTheJunctions(const std::string& real_class,
                                    std::initializer_list<std::pair<int, int>> frames,
                                    const JunctionDetectorOptions& without, double premise_px,
                                    double within_px) {
  for (const auto& [scene, index] : frames) {
    const double with_rule =
        WorstJunctionOffsetPx(real_class, scene, index, JunctionDetectorOptions());
    const double without_rule = WorstJunctionOffsetPx(real_class, scene, index, without);
    std::printf("%s scene %d frame %d: junctions within %.1f px with the rule, %.1f px without\n",
                real_class.c_str(), scene, index, with_rule, without_rule);
    EXPECT_GT(without_rule, premise_px) << scene << "/" << index;
    EXPECT_LT(with_rule, within_px) << scene << "/" << index;
  }
}

// A carpet runner down the middle of a tiled floor (scene 0) and one with a border (scene 4): the
// reference patch at the bottom centre shows the runner, so its edges look like the floor's
// boundary and the pair choice takes them. The tile joints between the runner and each wall run
// across the corridor: the floor rule takes the junctions above.
TEST(FloorRuleTest, TakesTheJunctionsBeyondACarpetRunner) {
  JunctionDetectorOptions without;
  without.floor_band_min_across = 0;
  ExpectTheRuleTakesTheJunctions("floor", {{0, 0}, {0, 4}, {4, 1}, {4, 2}}, without, 20.0, 3.0);
}

// Dark stripes painted 0.1-0.5 m from each wall on a tiled floor (scenes 8 and 9): a stripe's
// inner edge looks like the floor's boundary (dark above it) and the tile joints beyond it are
// too few for the floor rule; beyond the stripe's far edge the floor goes on, so the stripe rule
// takes the next line above, the junction.
TEST(StripeRuleTest, TakesTheJunctionsBeyondAFloorStripe) {
  JunctionDetectorOptions without;
  without.stripe_floor_likeness = 0;
  ExpectTheRuleTakesTheJunctions("floor", {{8, 2}, {8, 3}, {9, 3}}, without, 20.0, 3.0);
}

// A magenta runner with a tiled margin and a dark stripe beside it (scene 2; scene 9 has the
// stripe and a margin without joints on one side): the floor rule steps from the runner's edge
// over the tiled margin to the stripe's near edge, but the tiles beyond the stripe show too few
// joints, and the floor just below the runner's edge (magenta) is not the tiles' colour, so the
// stripe rule from the runner's edge finds nothing. From the floor rule's line, with the margin's
// own tiles as the floor, the stripe's far edge has floor beyond it and the next line above is the
// junction; the baseboard rule no longer steps back inside the stripe.
TEST(StripeRuleTest, TakesTheJunctionsBeyondAStripeBesideATiledMargin) {
  JunctionDetectorOptions without;
  without.stripe_floor_likeness = 0;
  ExpectTheRuleTakesTheJunctions("floor", {{2, 0}, {2, 12}, {2, 16}, {9, 0}, {9, 4}}, without,
                                 20.0, 3.0);
}

// The same runner where only one side's margin shows joints enough for the floor rule (scene 2
// frames 1 and 4, scene 9 frames 9 and 15): the other side's margin is taken to be of the same
// material (its line has the runner below it, as the line the floor rule moved from), and the
// stripe rule runs there with the first side's margin colour.
TEST(StripeRuleTest, TakesTheRunnersOtherSideBeyondItsStripe) {
  JunctionDetectorOptions without;
  without.stripe_floor_likeness = 0;
  ExpectTheRuleTakesTheJunctions("floor", {{2, 1}, {2, 4}, {9, 9}, {9, 15}}, without, 20.0, 3.0);
}

// Where the floor rule's line is the junction itself, a baseboard above it and a wall of the
// margin's colour above that look like a stripe with floor beyond it (mix scene 6 frame 0, scene
// 9 frame 16: the strip just above the junction is 0.6-0.8 alike to the floor, more than a thin
// stripe's half); and on a runner's other side the junction under a wall of the margin's colour
// has that colour above it (scene 0 frame 14: the margin's colour is also just below it, where a
// stripe's far edge has the stripe). The lines stay within 20 px of the junctions (taking the
// line beyond put them 22-176 px off; the pair chosen is off by up to 13 px at a support's end
// on these frames, its width within 1%).
TEST(StripeRuleTest, LeavesAJunctionUnderAWallOfTheMarginsColour) {
  for (const auto& [scene, index] : {std::pair<int, int>{6, 0}, {9, 16}, {0, 14}}) {
    const double offset = WorstJunctionOffsetPx("mix", scene, index, JunctionDetectorOptions());
    std::printf("mix scene %d frame %d: junctions within %.1f px\n", scene, index, offset);
    EXPECT_LT(offset, 20.0) << scene << "/" << index;
  }
}

// An option that must lie in [0, 1]: a value outside is rejected, and the reason names it.
void ExpectOutsideZeroToOneRejected(double JunctionDetectorOptions::*option, const char* name) {
  for (const double value : {-0.1, 1.5}) {
    JunctionDetectorOptions options;
    options.*option = value;
    std::string why;
    EXPECT_FALSE(options.Check(&why)) << name << " = " << value;
    EXPECT_NE(why.find(name), std::string::npos) << why;
  }
}

TEST(StripeRuleTest, BadOptionIsRejected) {
  ExpectOutsideZeroToOneRejected(&JunctionDetectorOptions::stripe_floor_likeness,
                                 "stripe_floor_likeness");
}

// A tiled floor up to a grey baseboard (scene 5 of the class with window bands): the last tile
// joint runs a few centimetres from the left wall, floor-coloured on both sides, and the pair
// choice takes it (the left wall about 7% too near; corridor_eval's width 3.7% short); the strip
// above the joint looks like the floor below it, so the inside-floor rule takes the line above
// (about 7 px out without the rule, within a pixel with it).
TEST(InsideFloorRuleTest, TakesTheJunctionAboveATileJointBesideTheWall) {
  JunctionDetectorOptions without;
  without.inside_floor_likeness = 0;
  ExpectTheRuleTakesTheJunctions("windows", {{5, 6}}, without, 5.0, 1.0);
}

// Frames 8 and 9 of the same scene: the joint's fit, far off, runs onto the junction (the two meet
// toward the vanishing point), and the refit follows the edge that runs the whole way, the
// junction (RefineJunction): within a pixel even without the rule (5-7 px out before).
TEST(InsideFloorRuleTest, AJointsFitBentOntoTheJunctionFollowsTheJunctionWithoutTheRule) {
  JunctionDetectorOptions without;
  without.inside_floor_likeness = 0;
  for (const int index : {8, 9}) {
    EXPECT_LT(WorstJunctionOffsetPx("windows", 5, index, without), 1.0) << index;
  }
}

TEST(InsideFloorRuleTest, BadOptionIsRejected) {
  ExpectOutsideZeroToOneRejected(&JunctionDetectorOptions::inside_floor_likeness,
                                 "inside_floor_likeness");
  ExpectOutsideZeroToOneRejected(&JunctionDetectorOptions::inside_floor_ridge_likeness,
                                 "inside_floor_ridge_likeness");
}

// A satin floor (scene 0 of the class with reflecting floors): the tile joint nearest each wall
// runs about 0.15 m from it, and the baseboard's faint reflection lies between, so the strip just
// above the joint is only 0.91-0.94 alike to the floor below it. The joint is darker than the
// floor on both its sides: the relaxed likeness for a ridge takes the junctions above.
TEST(InsideFloorRuleTest, TakesTheJunctionAboveAJointOnASatinFloor) {
  JunctionDetectorOptions without;
  without.inside_floor_ridge_likeness = 0;
  ExpectTheRuleTakesTheJunctions("satin", {{0, 0}, {0, 4}, {0, 10}}, without, 20.0, 3.0);
}

// A grey baseboard over a pink-brown tiled floor (scene 2 of the class with window bands): the
// last tile joint runs a centimetre or two from the left wall, so the junction looks like a dark
// ridge too, but the baseboard above it is only 0.83 alike to the floor. The default keeps the
// junction (or the joint, a few pixels from it); a ridge's likeness relaxed to 0.8 (here the
// "without" of the helper) would take the baseboard's top, more than 20 px out (the width about
// 10% too wide).
TEST(InsideFloorRuleTest, KeepsAJunctionWithAJointAtItsFoot) {
  JunctionDetectorOptions relaxed;
  relaxed.inside_floor_ridge_likeness = 0.8;
  ExpectTheRuleTakesTheJunctions("windows", {{2, 1}, {2, 4}}, relaxed, 15.0, 5.0);
}

// A runner with a dark border on a carpeted floor (scenes 6 and 7 of the class with every part):
// between the border and each wall the carpet has edges in every direction, as many vertical as
// across, so no tile joints say floor; its texture does (mostly oblique edges, densely). The
// runner's edges lie about 100 px from the junctions; the lines taken with the texture test end
// within 10 px of them (corridor_eval gives these two frames widths within 1% of the truth).
TEST(FloorRuleTest, TakesTheJunctionsBeyondARunnerOnCarpet) {
  JunctionDetectorOptions without;
  without.floor_band_texture_density = 0;
  ExpectTheRuleTakesTheJunctions("mix", {{6, 7}, {7, 14}}, without, 50.0, 10.0);
}

// A yellow runner with a purple border and tiled margins, seen from a head-mounted camera pitched
// 12-23 degrees down (scene 9 of the class with every part): near the image's side the margins'
// lines along the corridor stand within 15 degrees of vertical. Only when those are left out as
// lines toward the vanishing point do the margins' joints say floor, and the floor rule takes
// the junctions beyond the runner's edges.
TEST(FloorRuleTest, TakesTheJunctionsBeyondARunnerSeenSteeply) {
  JunctionDetectorOptions without;
  without.floor_band_min_across = 0;
  without.floor_band_texture_density = 0;
  ExpectTheRuleTakesTheJunctions("mix", {{9, 0}, {9, 1}}, without, 20.0, 3.0);
}

TEST(FloorRuleTest, BadOptionIsRejected) {
  JunctionDetectorOptions options;
  options.floor_band_min_across = -1;
  std::string why;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("floor_band_min_across"), std::string::npos) << why;
  options = JunctionDetectorOptions();
  options.floor_band_texture_density = 2;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("floor_band_texture_density"), std::string::npos) << why;
}

}  // namespace
}  // namespace corridor
