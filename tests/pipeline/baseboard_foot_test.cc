// A baseboard's foot on a carpet, end to end on the generator's real-buildings frames: the carpet's
// texture breaks the junction below the baseboard into pieces too short for the line search, so
// the pair search takes the baseboard's top, and that wall comes out too far by h / (h - 0.1);
// the band's lower edge found from the colours along candidate lines puts it back. A floor with
// stripes beside the walls (floor between wall and stripe) keeps its junctions. A baseboard nearly
// the floor's colour, on a tiled floor, is told by the floor's joints, which end at its foot; a
// floor-coloured band between a junction and a grout line is not. On a polished floor the
// baseboard's reflection is not the floor's edge. Truth: the renderer's scene width.
#include <cmath>
#include <cstdio>
#include <utility>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

double WidthError(const std::string& class_name, int scene, int frame, double* width = nullptr) {
  const testing_util::PresetFrame f = testing_util::RenderPreset(class_name, scene, frame);
  EXPECT_FALSE(f.frame.bgr.empty());
  RecoverDepthResult result;
  const Status status = RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &result);
  EXPECT_TRUE(status.ok()) << class_name << " " << scene << " " << frame << ": " << status.message();
  if (!status.ok() || !result.has_geometry) return NAN;
  if (width != nullptr) *width = result.geometry.width;
  std::printf("%s scene %d frame %d: width %.3f m, true %.3f m\n", class_name.c_str(), scene,
              frame, result.geometry.width, f.true_width);
  return std::abs(result.geometry.width - f.true_width) / f.true_width;
}

TEST(BaseboardFootTest, FindsTheFootOfABaseboardOnACarpet) {
  // Scene 4 of the carpet class: a grey baseboard 0.1 m high, a camera 0.66 m high.
  for (const int frame : {0, 4, 7}) EXPECT_LT(WidthError("carpet", 4, frame), 0.03) << frame;
}

TEST(BaseboardFootTest, KeepsTheJunctionAboveAStripeBesideTheWall) {
  // Scene 1 of the floor class: a dark stripe along each wall, floor between it and the wall.
  for (const int frame : {1, 3, 4}) EXPECT_LT(WidthError("floor", 1, frame), 0.03) << frame;
}

TEST(BaseboardFootTest, TheFloorsJointsEndAtTheFootOfADarkBaseboard) {
  // Scene 7 of the wainscot class: a dark baseboard on a dark tiled floor (band contrast about
  // 1.3 floor spreads), a camera 0.56 m high: its top puts the wall 21% too far.
  for (const int frame : {7, 10, 19}) EXPECT_LT(WidthError("wainscot", 7, frame), 0.03) << frame;
}

TEST(BaseboardFootTest, CeilingSidesThatSplitFindTheFaintFootOfTheWallTooFar) {
  // The same scene, frames where one wall's junction is the baseboard's top and its foot too
  // faint for the band test: the two ceiling sides are 22% apart, and the foot from the colours
  // below the wall with the higher side makes them agree (refused before, as two layouts fit).
  for (const int frame : {1, 5, 15}) {
    const testing_util::PresetFrame f = testing_util::RenderPreset("wainscot", 7, frame);
    RecoverDepthResult result;
    ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &result).ok()) << frame;
    EXPECT_LT(std::abs(result.geometry.width - f.true_width) / f.true_width, 0.03) << frame;
    EXPECT_TRUE(result.lower_line_taken) << frame;
    EXPECT_NE(result.fallback.find("foot of a band"), std::string::npos) << frame << ": " << result.fallback;
  }
}

TEST(BaseboardFootTest, AThinJointBeyondTheFootLeavesTheFootFound) {
  // Scene 2 of the floor class, frames 9 and 14: a joint along the wall beyond a baseboard's
  // foot; passing through the band's colour for a step, it once made the band look like floor
  // that goes on, and the frames were refused.
  for (const int frame : {9, 14}) EXPECT_LT(WidthError("floor", 2, frame), 0.03) << frame;
}

TEST(BaseboardFootTest, APolishedFloorsReflectionOfTheBaseboardIsNotTheFloorsEdge) {
  // Scenes 1 and 3 of the glossy class: a dark baseboard and its reflection read as one band,
  // whose lower edge (the reflection's) put both walls 13% too near; the junction is the band's
  // middle in slope.
  for (const auto& [scene, frame] : {std::pair<int, int>{1, 1}, {1, 2}, {3, 0}, {3, 1}}) {
    EXPECT_LT(WidthError("glossy", scene, frame), 0.03) << scene << "/" << frame;
  }
}

TEST(BaseboardFootTest, AReflectionIsFoundThroughADoorNearlyTheBaseboardsColourOrAboutTheJunction) {
  // Glossy scene 5: a grey baseboard on a grey-brown floor, its reflection unlike it by only 7% of
  // the wall-to-baseboard step. Scene 8: beside a door, a dark line mirrored inside the left band
  // changes it more than the step at the band's middle does. Both were 14% too narrow. Scene 3,
  // frame 2: the right junction was found between baseboard and reflection, only the left at the
  // reflection's lower edge (6% too narrow); the right band about its junction lets the left move.
  for (const auto& [scene, frame] : {std::pair<int, int>{5, 5}, {8, 5}, {3, 2}}) {
    EXPECT_LT(WidthError("glossy", scene, frame), 0.03) << scene << "/" << frame;
  }
}

TEST(BaseboardFootTest, OneWallsReflectionOnAFloorThatMirrorsTheLightsMovesBothWalls) {
  // Glossy scene 5, frames 1 and 4, and scene 8, frame 1: one wall's reflection is as dark as its
  // baseboard, so only the other wall reads as a reflection; the floor shows the ceiling's lights
  // and the unread wall's band is as high (relative to the camera) as the read one's, so it ends
  // at its reflection too. Both walls were taken at their reflections' lower edges, 13-15% too
  // near.
  for (const auto& [scene, frame] : {std::pair<int, int>{5, 1}, {5, 4}, {8, 1}}) {
    EXPECT_LT(WidthError("glossy", scene, frame), 0.03) << scene << "/" << frame;
  }
}

TEST(BaseboardFootTest, AReflectionDarkerThanItsBaseboardIsFoundAboveTheJunction) {
  // Glossy scene 7 frame 10 and scene 12 frame 0: the reflection is so much darker than the
  // baseboard that the junction is the band's largest change; the band's top is the largest
  // change beyond it. Both walls were taken at the reflections' lower edges, 7-14% too near.
  for (const auto& [scene, frame] : {std::pair<int, int>{7, 10}, {12, 0}}) {
    EXPECT_LT(WidthError("glossy", scene, frame), 0.03) << scene << "/" << frame;
  }
}

TEST(BaseboardFootTest, OneWallThatReadsAsAReflectionOnADiffuseFloorMovesNothing) {
  // Rail scene 6 frame 6, mix scene 6 frame 1: a baseboard with a darker foot reads as a
  // reflection on one wall, on a floor that shows no lights; both junctions stay where they are.
  EXPECT_LT(WidthError("rail", 6, 6), 0.03);
  EXPECT_LT(WidthError("mix", 6, 1), 0.03);
}

TEST(BaseboardFootTest, AFloorColouredBandBelowTheJunctionIsFloor) {
  // Scene 9 of the low class, frame 1: a grout line along the wall below the junction, the band
  // between them floor-coloured (0.5 floor spreads) and crossed by the joints only in part.
  EXPECT_LT(WidthError("low", 9, 1), 0.03);
}

}  // namespace
}  // namespace corridor
