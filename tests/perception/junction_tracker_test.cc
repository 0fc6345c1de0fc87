// TrackJunctions and JunctionTrack: the junctions of a rendered corridor's next frame, sought near
// the previous frame's, land on the generator's true junctions (projected by hand from the true
// geometry); a track is lost when the lines moved too far; bad inputs and options say why; the
// track's trust follows the whole searches' agreement and the re-search interval.
#include "perception/junction_tracker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "corridor_depth/camera.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

// The point of `line` at image row v.
Eigen::Vector2d AtRow(const Eigen::Vector3d& line, double v) {
  return {-(line.y() * v + line.z()) / line.x(), v};
}

// Largest distance from `truth` of `junction`'s line between its ends' rows.
double LargestDistance(const JunctionLine& junction, const Eigen::Vector3d& truth) {
  const double v0 = std::min(junction.near_end.y(), junction.far_end.y());
  const double v1 = std::max(junction.near_end.y(), junction.far_end.y());
  double worst = 0;
  for (double v = v0; v <= v1; v += 1) {
    worst = std::max(worst, std::abs(truth.dot(AtRow(junction.line, v).homogeneous())));
  }
  return worst;
}

class JunctionTrackerTest : public ::testing::Test {
 protected:
  // A plain corridor at 640x480 (no boxes, so that no lower alternative needs the ceiling check).
  synth::Frame Render(const synth::CameraPose& pose) const {
    return testing_util::RenderCorridorFrame(camera_, 2.2, 2.7, 11, pose, 0.0);
  }

  const Camera camera_ = Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180, 0.66);
  const synth::CameraPose pose0_{0.03, 0.05, 0.10, 0.66, 3.0};
  // 0.3 m on, turned 0.01 rad, 3 cm to the side: a frame later at walking pace and 5 Hz.
  const synth::CameraPose pose1_{0.04, 0.052, 0.13, 0.66, 3.3};
  const JunctionDetectorOptions detector_;
  const JunctionTrackerOptions options_;
};

TEST_F(JunctionTrackerTest, TheNextFramesJunctionsLandOnTheTrueOnes) {
  const synth::Frame frame0 = Render(pose0_), frame1 = Render(pose1_);
  ASSERT_FALSE(frame0.bgr.empty());
  ASSERT_FALSE(frame1.bgr.empty());
  JunctionPair previous;
  ASSERT_TRUE(DetectJunctions(frame0.bgr, detector_, &previous).ok());
  ASSERT_FALSE(previous.has_left_lower || previous.has_right_lower) << "premise: no alternative";
  JunctionPair tracked;
  std::string why;
  ASSERT_TRUE(TrackJunctions(frame1.bgr, previous, detector_, options_, &tracked, &why)) << why;
  EXPECT_TRUE(tracked.status.ok());
  for (const int side : {-1, 1}) {
    const JunctionLine& line = side < 0 ? tracked.left : tracked.right;
    const Eigen::Vector3d truth = testing_util::TrueJunction(frame1.truth, camera_, side);
    const Eigen::Vector3d truth_before = testing_util::TrueJunction(frame0.truth, camera_, side);
    // Premise: the junction moved (the previous line is not the answer).
    EXPECT_GT(LargestDistance(line, truth_before), 3.0) << "side " << side;
    EXPECT_LT(LargestDistance(line, truth), 1.0) << "side " << side;
    EXPECT_GT(std::abs(line.near_end.y() - line.far_end.y()), 60) << "side " << side;
    EXPECT_GE(line.support.size(), 20u) << "side " << side;
    EXPECT_GT(line.confidence, 0.0) << "side " << side;
  }
  // The vanishing point is the two tracked lines' intersection.
  EXPECT_NEAR(tracked.left.line.dot(tracked.vanishing_point.homogeneous()), 0, 1e-6);
  EXPECT_NEAR(tracked.right.line.dot(tracked.vanishing_point.homogeneous()), 0, 1e-6);
}

// The same frames: a tracked line weaker than min_line_confidence leaves the frame to the whole
// search, and says which; the tracked lines' own confidence sets where that happens.
TEST_F(JunctionTrackerTest, AWeakTrackedLineIsLeftToTheWholeSearch) {
  const synth::Frame frame0 = Render(pose0_), frame1 = Render(pose1_);
  JunctionPair previous;
  ASSERT_TRUE(DetectJunctions(frame0.bgr, detector_, &previous).ok());
  JunctionPair tracked;
  std::string why;
  ASSERT_TRUE(TrackJunctions(frame1.bgr, previous, detector_, options_, &tracked, &why)) << why;
  const double weaker = std::min(tracked.left.confidence, tracked.right.confidence);
  ASSERT_GE(weaker, options_.min_line_confidence) << "premise: a plain corridor's lines are strong";
  JunctionTrackerOptions demanding = options_;
  demanding.min_line_confidence = std::min(1.0, weaker + 1e-6);
  JunctionPair again;
  EXPECT_FALSE(TrackJunctions(frame1.bgr, previous, detector_, demanding, &again, &why));
  EXPECT_NE(why.find("weak"), std::string::npos) << why;
  demanding.min_line_confidence = weaker;
  EXPECT_TRUE(TrackJunctions(frame1.bgr, previous, detector_, demanding, &again, &why)) << why;
}

TEST_F(JunctionTrackerTest, JunctionsThatMovedFarAreLost) {
  const synth::Frame frame0 = Render(pose0_);
  synth::CameraPose far_pose = pose0_;
  far_pose.offset += 0.45;  // Both junctions move tens of pixels.
  far_pose.yaw -= 0.08;
  const synth::Frame moved = Render(far_pose);
  JunctionPair previous;
  ASSERT_TRUE(DetectJunctions(frame0.bgr, detector_, &previous).ok());
  JunctionPair tracked;
  tracked.floor_texture = 0.5;  // A marker: a lost track leaves *tracked untouched.
  std::string why;
  EXPECT_FALSE(TrackJunctions(moved.bgr, previous, detector_, options_, &tracked, &why));
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(tracked.floor_texture, 0.5);
}

TEST_F(JunctionTrackerTest, BadInputsSayWhy) {
  const synth::Frame frame0 = Render(pose0_);
  JunctionPair previous;
  ASSERT_TRUE(DetectJunctions(frame0.bgr, detector_, &previous).ok());
  JunctionPair tracked;
  std::string why;
  EXPECT_FALSE(TrackJunctions(cv::Mat(), previous, detector_, options_, &tracked, &why));
  EXPECT_NE(why.find("8-bit BGR"), std::string::npos) << why;
  cv::Mat grey;
  cv::cvtColor(frame0.bgr, grey, cv::COLOR_BGR2GRAY);
  EXPECT_FALSE(TrackJunctions(grey, previous, detector_, options_, &tracked, &why));
  EXPECT_NE(why.find("8-bit BGR"), std::string::npos) << why;
  JunctionPair none;
  none.status = Status::NoCorridorFound("no pair");
  EXPECT_FALSE(TrackJunctions(frame0.bgr, none, detector_, options_, &tracked, &why));
  EXPECT_NE(why.find("no junction pair"), std::string::npos) << why;
  // A pair with a lower alternative is left to the whole search and its ceiling check.
  JunctionPair with_lower = previous;
  with_lower.has_right_lower = true;
  with_lower.right_lower = previous.right;
  EXPECT_FALSE(TrackJunctions(frame0.bgr, with_lower, detector_, options_, &tracked, &why));
  EXPECT_NE(why.find("lower alternative"), std::string::npos) << why;
}

TEST(JunctionTrackerOptionsTest, EachBadOptionIsNamed) {
  EXPECT_TRUE(JunctionTrackerOptions().Check(nullptr));
  const auto message = [](JunctionTrackerOptions o) {
    std::string why;
    EXPECT_FALSE(o.Check(&why));
    return why;
  };
  JunctionTrackerOptions o;
  o.reach_fraction = 0;
  EXPECT_NE(message(o).find("reach_fraction"), std::string::npos);
  o = JunctionTrackerOptions();
  o.sample_step = 0;
  EXPECT_NE(message(o).find("sample_step"), std::string::npos);
  o = JunctionTrackerOptions();
  o.threshold = -1;
  EXPECT_NE(message(o).find("threshold"), std::string::npos);
  o = JunctionTrackerOptions();
  o.min_support = 1.5;
  EXPECT_NE(message(o).find("min_support"), std::string::npos);
  o = JunctionTrackerOptions();
  o.max_shift_fraction = -0.1;
  EXPECT_NE(message(o).find("max_shift_fraction"), std::string::npos);
  o = JunctionTrackerOptions();
  o.min_line_confidence = 1.5;
  EXPECT_NE(message(o).find("min_line_confidence"), std::string::npos);
  o = JunctionTrackerOptions();
  o.max_lines_per_band = 0;
  EXPECT_NE(message(o).find("max_lines_per_band"), std::string::npos);
  o = JunctionTrackerOptions();
  o.extend_fraction = 2;
  EXPECT_NE(message(o).find("extend_fraction"), std::string::npos);
  o = JunctionTrackerOptions();
  o.support_distance_px = 0;
  EXPECT_NE(message(o).find("support_distance_px"), std::string::npos);
  o = JunctionTrackerOptions();
  o.redetect_interval = -1;
  EXPECT_NE(message(o).find("redetect_interval"), std::string::npos);
  o = JunctionTrackerOptions();
  o.agreement_px = std::nan("");
  EXPECT_NE(message(o).find("agreement_px"), std::string::npos);
}

// A junction pair whose lines are the image lines through the given ends.
JunctionPair PairThrough(const Eigen::Vector2d& l0, const Eigen::Vector2d& l1,
                         const Eigen::Vector2d& r0, const Eigen::Vector2d& r1) {
  JunctionPair pair;
  const auto line = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    JunctionLine j;
    j.line = a.homogeneous().cross(b.homogeneous());
    j.line /= j.line.head<2>().norm();
    j.near_end = a;
    j.far_end = b;
    return j;
  };
  pair.left = line(l0, l1);
  pair.right = line(r0, r1);
  return pair;
}

TEST(SameJunctionsTest, LinesWithinTheToleranceAtBothEndsAreTheSame) {
  const JunctionPair a = PairThrough({0, 400}, {300, 250}, {640, 420}, {340, 250});
  // b's right line is 1.5 px beside a's at its near end and on it at its far end.
  JunctionPair b = a;
  const Eigen::Vector2d n = a.right.line.head<2>();
  b.right.near_end = a.right.near_end + 1.5 * n;
  b.right.line = b.right.near_end.homogeneous().cross(b.right.far_end.homogeneous());
  b.right.line /= b.right.line.head<2>().norm();
  EXPECT_TRUE(SameJunctions(a, b, 2.0));
  EXPECT_FALSE(SameJunctions(a, b, 1.0));
  JunctionPair failed = a;
  failed.status = Status::NoCorridorFound("none");
  EXPECT_FALSE(SameJunctions(a, failed, 100.0));
}

TEST(JunctionTrackTest, TrustFollowsTheWholeSearchesAgreementAndTheInterval) {
  const JunctionPair pair = PairThrough({0, 400}, {300, 250}, {640, 420}, {340, 250});
  const cv::Size size(640, 480);
  JunctionTrack track;
  EXPECT_EQ(track.Previous(size), nullptr);
  EXPECT_FALSE(track.Trusted(2));
  track.Searched(pair, size, false);  // The first frame: nothing tracked into it.
  ASSERT_NE(track.Previous(size), nullptr);
  EXPECT_EQ(track.Previous(cv::Size(320, 240)), nullptr);  // Another size: no previous lines.
  EXPECT_FALSE(track.Trusted(2));
  track.Searched(pair, size, true);  // A whole search agreed with its tracked pair.
  EXPECT_TRUE(track.Trusted(2));
  track.Tracked(pair, size);
  EXPECT_TRUE(track.Trusted(2));
  track.Tracked(pair, size);
  EXPECT_FALSE(track.Trusted(2));     // Two tracked frames in a row: the next is searched whole.
  track.Searched(pair, size, false);  // ... and disagreed.
  EXPECT_FALSE(track.Trusted(2));
  JunctionPair lost;
  lost.status = Status::NoCorridorFound("none");
  track.Searched(lost, size, false);
  EXPECT_EQ(track.Previous(size), nullptr);
  EXPECT_FALSE(track.Trusted(2));

  JunctionTrack forever;  // Interval 0: never searched whole again once trusted.
  forever.Searched(pair, size, true);
  for (int i = 0; i < 50; ++i) forever.Tracked(pair, size);
  EXPECT_TRUE(forever.Trusted(0));
}

}  // namespace
}  // namespace corridor
