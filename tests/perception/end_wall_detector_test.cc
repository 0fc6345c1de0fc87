// The end-wall detector on the generator's corridors (an independent ray caster): with the true
// geometry it finds an end wall where the scene has one, within 3% of its distance, and takes no
// tile grout, door or light for one where the end wall lies beyond range.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "perception/end_wall_detector.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

struct Case {
  double length;  // The scene's end wall, m from its start.
  synth::CameraPose pose;
};

class EndWallOnGeneratedCorridor : public ::testing::TestWithParam<Case> {};

TEST_P(EndWallOnGeneratedCorridor, IsFoundWithin3Percent) {
  const Case c = GetParam();
  synth::SceneOptions scene;
  scene.length = c.length;
  scene.door_density = 0.6;
  scene.clutter = 0.2;
  scene.seed = 3;
  const Camera camera = synth::PaperCamera(c.pose.height);
  synth::Frame frame;
  ASSERT_TRUE(synth::RenderFrame(scene, camera, c.pose, &frame).ok());
  EndWallEstimate estimate;
  ASSERT_TRUE(
      DetectEndWall(frame.bgr, camera, frame.truth, EndWallDetectorOptions(), &estimate).ok());
  const double truth = c.length - c.pose.distance;  // Z_W of the end wall, by the scene's layout.
  std::printf("end wall %.2f m: found %d at %.3f m (support %.2f, beyond %.2f, corner %.2f) %s\n",
              truth, estimate.found, estimate.distance, estimate.support, estimate.beyond,
              estimate.corner, estimate.reason.c_str());
  ASSERT_TRUE(estimate.found) << estimate.reason;
  EXPECT_NEAR(estimate.distance, truth, 0.03 * truth);
  // The same search on edges computed once for the pipeline's searches (the same edges: the same
  // estimate); edges of another image size are not used.
  ImageEdges shared;
  ASSERT_TRUE(ComputeImageEdges(frame.bgr, &shared));
  ImageEdges other;
  ASSERT_TRUE(ComputeImageEdges(frame.bgr.rowRange(0, frame.bgr.rows / 2), &other));
  for (const ImageEdges* edges : {&shared, &other}) {
    EndWallEstimate again;
    ASSERT_TRUE(DetectEndWall(frame.bgr, camera, frame.truth, EndWallDetectorOptions(), &again,
                              edges)
                    .ok());
    EXPECT_EQ(again.found, estimate.found);
    EXPECT_EQ(again.distance, estimate.distance);
    EXPECT_EQ(again.points, estimate.points);
  }
  // At the image's own resolution: the whole image's edges given, or only the rows the search
  // looks at computed here (below the horizon, and above it as far as the corners it probes
  // reach): the same wall, within a few millimetres.
  EndWallDetectorOptions full_size;
  full_size.max_work_width = frame.bgr.cols;
  EndWallEstimate own_rows, whole;
  ASSERT_TRUE(DetectEndWall(frame.bgr, camera, frame.truth, full_size, &own_rows).ok());
  ASSERT_TRUE(DetectEndWall(frame.bgr, camera, frame.truth, full_size, &whole, &shared).ok());
  std::printf("at full size: own rows %d at %.4f m (%d points), whole image %d at %.4f m (%d)\n",
              own_rows.found, own_rows.distance, own_rows.points, whole.found, whole.distance,
              whole.points);
  ASSERT_TRUE(whole.found) << whole.reason;
  ASSERT_TRUE(own_rows.found) << own_rows.reason;
  EXPECT_NEAR(own_rows.distance, whole.distance, 0.002 * whole.distance);
}

INSTANTIATE_TEST_SUITE_P(
    Poses, EndWallOnGeneratedCorridor,
    ::testing::Values(Case{9, {0.06, 0.03, 0.1, 0.66, 2.0}}, Case{12, {0.05, -0.04, -0.2, 0.66, 2.0}},
                      Case{14, {0.09, 0.0, 0.25, 0.62, 3.0}}, Case{8, {0.02, 0.06, 0.0, 0.66, 2.5}}));

// The paper preset's corridors end 40 m and more away: grout lines across the floor every 0.6 m,
// doors and lights must not make an end wall (true geometry, so only the detector is tested).
TEST(EndWallDetectorTest, NoEndWallWhereTheCorridorGoesOn) {
  int frames = 0, found = 0;
  for (const synth::ScenePreset& preset : synth::PaperPreset()) {
    for (size_t i = 0; i < preset.poses.size(); i += 7) {
      synth::Frame frame;
      ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, preset.poses[i], &frame).ok());
      EndWallEstimate estimate;
      ASSERT_TRUE(DetectEndWall(frame.bgr, preset.camera, frame.truth, EndWallDetectorOptions(),
                                &estimate)
                      .ok());
      ++frames;
      if (estimate.found) {
        ++found;
        ADD_FAILURE() << preset.name << " frame " << i << ": end wall at " << estimate.distance
                      << " m, the scene's is at "
                      << preset.scene.length - preset.poses[i].distance << " m";
      }
    }
  }
  EXPECT_GE(frames, 18);
  EXPECT_EQ(found, 0);
}

TEST(EndWallDetectorTest, BadInputsGiveAStatus) {
  const Camera camera = synth::PaperCamera(0.66);
  CorridorGeometry g;
  g.width = 2;
  g.camera_height = 0.66;
  EndWallEstimate estimate;
  EXPECT_EQ(DetectEndWall(cv::Mat(), camera, g, EndWallDetectorOptions(), &estimate).code(),
            StatusCode::kInvalidArgument);
  EndWallDetectorOptions bad;
  bad.far_distance = 1;
  std::string why;
  EXPECT_FALSE(bad.Check(&why));
  EXPECT_NE(why.find("far_distance"), std::string::npos) << why;
  const cv::Mat black(camera.image_height, camera.image_width, CV_8UC3, cv::Scalar(0, 0, 0));
  ASSERT_TRUE(DetectEndWall(black, camera, g, EndWallDetectorOptions(), &estimate).ok());
  EXPECT_FALSE(estimate.found);
  EXPECT_FALSE(estimate.reason.empty());
}

}  // namespace
}  // namespace corridor
