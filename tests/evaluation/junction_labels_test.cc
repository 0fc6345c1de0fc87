// Scoring reported junctions against hand labels, on hand-computed cases: a level camera looking
// down the middle of a 2 m corridor 1 m above the floor sees its left junction on u + v = cx + cy
// and its right one on u - v = cx - cy (the 3D lines (-1, 1, s) and (1, 1, s) projected).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "evaluation/junction_labels.h"

namespace corridor {
namespace {

Camera TestCamera() {
  Camera c;
  c.image_width = 640, c.image_height = 480;
  c.fx = c.fy = 400, c.cx = 319.5, c.cy = 239.5;
  c.mount_height = 1.0;
  return c;
}

CorridorGeometry Centred() {
  CorridorGeometry g;
  g.width = 2.0, g.camera_height = 1.0;
  return g;
}

// A label whose left segment lies `shift` px below the true left junction (right side hidden).
JunctionLabel LeftLabel(double shift) {
  const Camera c = TestCamera();
  JunctionLabel label;
  label.file = "x.png", label.width = 640, label.height = 480, label.kind = "corridor";
  label.has_side[0] = true;
  label.side[0] = {Eigen::Vector2d(c.cx - 200, c.cy + 200 + shift),
                   Eigen::Vector2d(c.cx - 100, c.cy + 100 + shift)};
  return label;
}

TEST(JunctionLabels, ProjectsTheHandComputedJunctions) {
  const Camera c = TestCamera();
  Eigen::Vector3d left, right;
  ASSERT_TRUE(ProjectedJunction(Centred(), c, 0, &left));
  ASSERT_TRUE(ProjectedJunction(Centred(), c, 1, &right));
  const double r = 1 / std::sqrt(2.0);
  // Up to sign: (1, 1, -(cx + cy)) / sqrt(2) and (1, -1, -(cx - cy)) / sqrt(2).
  const double sl = left.x() > 0 ? 1 : -1, sr = right.x() > 0 ? 1 : -1;
  EXPECT_NEAR(sl * left.x(), r, 1e-9);
  EXPECT_NEAR(sl * left.y(), r, 1e-9);
  EXPECT_NEAR(sl * left.z(), -(c.cx + c.cy) * r, 1e-6);
  EXPECT_NEAR(sr * right.x(), r, 1e-9);
  EXPECT_NEAR(sr * right.y(), -r, 1e-9);
  EXPECT_NEAR(sr * right.z(), -(c.cx - c.cy) * r, 1e-6);
}

// A frame recovered level from a roll of 90 degrees: the level camera's left junction
// (u - cx) + (v - cy) = 0, turned by Rz(90 deg) ((x, y) -> (-y, x) about the principal point),
// is (u - cx) - (v - cy) = 0 in the frame's pixels.
TEST(JunctionLabels, ARolledFramesJunctionIsTurnedIntoItsPixels) {
  const Camera c = TestCamera();
  Eigen::Vector3d left;
  ASSERT_TRUE(ProjectedJunction(Centred(), c, 0, &left, M_PI / 2));
  const double r = 1 / std::sqrt(2.0), s = left.x() > 0 ? 1 : -1;
  EXPECT_NEAR(s * left.x(), r, 1e-9);
  EXPECT_NEAR(s * left.y(), -r, 1e-9);
  EXPECT_NEAR(s * left.z(), -(c.cx - c.cy) * r, 1e-6);
}

TEST(JunctionLabels, ALineAKnownNumberOfPixelsOff) {
  const Camera c = TestCamera();
  // A vertical shift of s px is s / sqrt(2) px from a 45-degree line.
  const struct {
    double shift;
    LabelVerdict verdict;
  } cases[] = {{0, LabelVerdict::kRight},
               {6, LabelVerdict::kRight},         // 4.24 px = 0.88% of 480.
               {-30, LabelVerdict::kRough},       // 21.2 px = 4.4%.
               {40, LabelVerdict::kOkButWrong}};  // 28.3 px = 5.9%.
  for (const auto& k : cases) {
    const LabelScore score = ScoreAgainstLabel(LeftLabel(k.shift), true, Centred(), c);
    EXPECT_NEAR(score.side_error[0], std::abs(k.shift) / std::sqrt(2.0) / 480, 1e-9) << k.shift;
    EXPECT_EQ(score.verdict, k.verdict) << k.shift;
    EXPECT_LT(score.side_error[1], 0) << "the right side is hidden: not scored";
  }
}

TEST(JunctionLabels, TheWorseEndOfTheSegmentCounts) {
  // The near point on the line, the far one 24 px (17 px from the line, 3.5%) below it.
  const Camera c = TestCamera();
  JunctionLabel label = LeftLabel(0);
  label.side[0][1].y() += 24;
  const LabelScore score = ScoreAgainstLabel(label, true, Centred(), c);
  EXPECT_NEAR(score.side_error[0], 24 / std::sqrt(2.0) / 480, 1e-9);
  EXPECT_EQ(score.verdict, LabelVerdict::kRough);
}

TEST(JunctionLabels, ARefusedFrameIsRefusedWhateverItsGeometry) {
  const LabelScore score = ScoreAgainstLabel(LeftLabel(0), false, Centred(), TestCamera());
  EXPECT_EQ(score.verdict, LabelVerdict::kRefused);
  EXPECT_LT(score.side_error[0], 0);
}

TEST(JunctionLabels, AWallTheGeometryCannotProjectIsWrong) {
  CorridorGeometry g = Centred();
  g.width = 0;  // No walls.
  EXPECT_EQ(ScoreAgainstLabel(LeftLabel(0), true, g, TestCamera()).verdict,
            LabelVerdict::kOkButWrong);
}

TEST(JunctionLabels, ReadsTheLabelFile) {
  const std::string path = ::testing::TempDir() + "/junctions_test.csv";
  {
    std::ofstream out(path);
    out << "file,width,height,lx1,ly1,lx2,ly2,rx1,ry1,rx2,ry2,vpx,vpy,kind,quality,notes,fx,fy,cx,"
           "cy\n"
        << "a.jpg,512,384,1,2,3,4,,,,,5,6,corridor,sure,\"a note, with a comma\",,,,\n"
        << "b.png,640,480,1,2,3,4,5,6,7,8,9,9,other,approx,,371.9,372.1,315.6,250.5\n";
  }
  std::vector<JunctionLabel> labels;
  ASSERT_TRUE(ReadJunctionLabels(path, &labels).ok());
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_EQ(labels[0].file, "a.jpg");
  EXPECT_TRUE(labels[0].has_side[0]);
  EXPECT_FALSE(labels[0].has_side[1]);
  EXPECT_FALSE(labels[0].has_camera);
  EXPECT_EQ(labels[0].side[0][1], Eigen::Vector2d(3, 4));
  EXPECT_EQ(labels[1].kind, "other");
  EXPECT_TRUE(labels[1].has_camera);
  EXPECT_DOUBLE_EQ(labels[1].cy, 250.5);
  {
    std::ofstream out(path);
    out << "file,width,height,lx1,ly1,lx2,ly2,rx1,ry1,rx2,ry2,kind,quality,fx,fy,cx,cy\n"
        << "a.jpg,512,384,1,2,3,,,,,,corridor,sure,,,,\n";
  }
  const Status status = ReadJunctionLabels(path, &labels);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("line 2"), std::string::npos) << status.message();
}

}  // namespace
}  // namespace corridor
