// The ceiling search on generated corridors, given their true walls (from truth), against the
// true ceiling height; and no ceiling where the image shows none.
#include "perception/ceiling_detector.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "corridor_depth/corridor_frame.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

// The paper preset's six end-wall scenes, each with its fifth frame rendered.
struct EndWallFrame {
  synth::ScenePreset preset;
  synth::Frame frame;
};
std::vector<EndWallFrame> PaperEndWallFrames() {
  std::vector<EndWallFrame> out;
  for (const auto& preset : synth::PaperPreset()) {
    if (preset.name.find("_E") == std::string::npos) continue;
    EndWallFrame f{preset, synth::Frame()};
    const synth::CorridorScene scene = synth::BuildScene(preset.scene);
    EXPECT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses[4], &f.frame).ok())
        << preset.name;
    out.push_back(std::move(f));
  }
  return out;
}

TEST(CeilingDetectorTest, FindsTheCeilingHeightOfGeneratedCorridors) {
  int checked = 0;
  for (const EndWallFrame& f : PaperEndWallFrames()) {
    const synth::ScenePreset& preset = f.preset;
    const synth::Frame& frame = f.frame;
    ASSERT_FALSE(frame.bgr.empty()) << preset.name;
    CeilingEstimate estimate;
    ASSERT_TRUE(
        DetectCeiling(frame.bgr, preset.camera, frame.truth, CeilingDetectorOptions(), &estimate)
            .ok());
    ASSERT_TRUE(estimate.found) << preset.name << ": " << estimate.reason;
    EXPECT_NEAR(estimate.height, preset.scene.ceiling_height, 0.03 * preset.scene.ceiling_height)
        << preset.name;
    EXPECT_GT(estimate.points, 20);
    // On edges computed once over the whole image (as the pipeline shares them with the end-wall
    // search): Canny's hysteresis sees a little more than on the searched rows alone.
    ImageEdges shared;
    ASSERT_TRUE(ComputeImageEdges(frame.bgr, &shared));
    CeilingEstimate again;
    ASSERT_TRUE(DetectCeiling(frame.bgr, preset.camera, frame.truth, CeilingDetectorOptions(),
                              &again, &shared)
                    .ok());
    ASSERT_TRUE(again.found) << preset.name << ": " << again.reason;
    EXPECT_NEAR(again.height, estimate.height, 0.01) << preset.name;
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

// Many corridor lines' supports read on one band of edges over all their rows are each the
// support of that line read alone (its own band), on the image's edges computed once.
TEST(CeilingDetectorTest, LinesReadTogetherHaveTheirOwnSupports) {
  const std::vector<EndWallFrame> frames = PaperEndWallFrames();
  ASSERT_FALSE(frames.empty());
  const EndWallFrame& f = frames.front();
  ASSERT_FALSE(f.frame.bgr.empty());
  const CorridorGeometry& g = f.frame.truth;
  ImageEdges shared;
  ASSERT_TRUE(ComputeImageEdges(f.frame.bgr, &shared));
  const CeilingDetectorOptions o;
  const double y_ceiling = g.camera_height - f.preset.scene.ceiling_height;
  for (const double y : {g.camera_height, y_ceiling}) {
    std::vector<double> xs;
    for (int i = 0; i <= 10; ++i) {
      const double r = 0.5 + 0.05 * i;
      xs.push_back(-g.LeftDistance() * r);
      xs.push_back(g.RightDistance() * r);
    }
    const std::vector<double> together =
        CorridorLinesSupport(f.frame.bgr, f.preset.camera, g, xs, y, o, &shared);
    ASSERT_EQ(together.size(), xs.size());
    for (size_t k = 0; k < xs.size(); ++k) {
      EXPECT_EQ(together[k],
                CorridorLineSupport(f.frame.bgr, f.preset.camera, g, xs[k], y, o, &shared))
          << y << " " << xs[k];
    }
    // Not all empty: a true wall's line (r = 1, the last two) is on edges.
    EXPECT_GT(std::max(together[xs.size() - 2], together[xs.size() - 1]), 0.5) << y;
  }
  EXPECT_TRUE(CorridorLinesSupport(f.frame.bgr, f.preset.camera, g, {}, g.camera_height, o)
                  .empty());
}

// The search scores every third height first and then the heights around the best ones: it
// must find the same best support, per side and for the two sides together, as scoring every
// height does (each height searched alone, on the same shared edges).
TEST(CeilingDetectorTest, CoarseToFineFindsTheBestOfEveryHeight) {
  int checked = 0;
  for (const EndWallFrame& f : PaperEndWallFrames()) {
    const synth::ScenePreset& preset = f.preset;
    const synth::Frame& frame = f.frame;
    ASSERT_FALSE(frame.bgr.empty()) << preset.name;
    ImageEdges shared;
    ASSERT_TRUE(ComputeImageEdges(frame.bgr, &shared));
    const CeilingDetectorOptions options;
    CeilingEstimate estimate;
    ASSERT_TRUE(
        DetectCeiling(frame.bgr, preset.camera, frame.truth, options, &estimate, &shared).ok());
    double best_side[2] = {0, 0}, best_sum = 0;
    CeilingEstimate best_alone;  // The height of the best sum, searched alone.
    int heights = 0;
    const double lo = std::max(options.min_height, frame.truth.camera_height + 0.1);
    for (double height = lo; height <= options.max_height; height += options.step, ++heights) {
      CeilingDetectorOptions one = options;
      one.min_height = height;
      one.max_height = height + 0.5 * options.step;
      CeilingEstimate alone;
      ASSERT_TRUE(
          DetectCeiling(frame.bgr, preset.camera, frame.truth, one, &alone, &shared).ok());
      for (int side = 0; side < 2; ++side) {
        best_side[side] = std::max(best_side[side], alone.side_support[side]);
      }
      const double sum = alone.side_support[0] + alone.side_support[1];
      if (sum > best_sum) best_sum = sum, best_alone = alone;
    }
    ASSERT_GT(heights, 100);
    for (int side = 0; side < 2; ++side) {
      EXPECT_DOUBLE_EQ(estimate.side_support[side], best_side[side]) << preset.name;
    }
    // The chosen lines are those of the best sum (the first, as every height in turn keeps it):
    // the same supports on the samples in view, and the same estimate from the edge pixels near
    // them.
    ASSERT_GT(best_sum, 0) << preset.name;
    EXPECT_DOUBLE_EQ(estimate.left_support, best_alone.left_support) << preset.name;
    EXPECT_DOUBLE_EQ(estimate.right_support, best_alone.right_support) << preset.name;
    EXPECT_DOUBLE_EQ(estimate.height, best_alone.height) << preset.name;
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

// The ceiling criterion for the search itself: given the walls, every paper-preset scene
// (the hard ones too: clutter, doors, glossy floors), every third frame, within 3%.
TEST(CeilingDetectorTest, EveryPaperSceneWithinThreePercentGivenTheWalls) {
  int checked = 0;
  for (const auto& preset : synth::PaperPreset()) {
    const synth::CorridorScene scene = synth::BuildScene(preset.scene);
    for (size_t i = 0; i < preset.poses.size(); i += 3) {
      synth::Frame frame;
      ASSERT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses[i], &frame).ok());
      CeilingEstimate estimate;
      ASSERT_TRUE(DetectCeiling(frame.bgr, preset.camera, frame.truth, CeilingDetectorOptions(),
                                &estimate)
                      .ok());
      ASSERT_TRUE(estimate.found) << preset.name << " frame " << i << ": " << estimate.reason;
      EXPECT_NEAR(estimate.height, preset.scene.ceiling_height, 0.03 * preset.scene.ceiling_height)
          << preset.name << " frame " << i;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 45);
}

// A green wall under a grey ceiling of the same brightness: the junction is a colour edge only.
TEST(CeilingDetectorTest, FindsAColourOnlyCeilingJunction) {
  const synth::ScenePreset preset = synth::PaperPreset().front();
  synth::CorridorScene scene = synth::BuildScene(preset.scene);
  scene.wall_color = cv::Vec3f(0.50f, 0.72f, 0.52f);  // BGR: green.
  const float luma = 0.114f * 0.50f + 0.587f * 0.72f + 0.299f * 0.52f;
  scene.ceiling_color = cv::Vec3f(luma, luma, luma);
  synth::Frame frame;
  ASSERT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses[4], &frame).ok());
  // The test means something only if grey levels hardly change across the true junction.
  cv::Mat gray;
  cv::cvtColor(frame.bgr, gray, cv::COLOR_BGR2GRAY);
  const CorridorGeometry& g = frame.truth;
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const double y = g.camera_height - preset.scene.ceiling_height;
  double step = 0;
  int visible = 0;
  for (const double z : {4.0, 6.0, 8.0, 10.0}) {
    // Just inside the ceiling, then just down the wall, 10 cm from the junction.
    const Vec3<double> ceiling = r.ToCamera({-g.LeftDistance() + 0.1, y, z});
    const Vec3<double> wall = r.ToCamera({-g.LeftDistance(), y + 0.1, z});
    const Eigen::Vector2d a = preset.camera.Project({ceiling.x, ceiling.y, ceiling.z});
    const Eigen::Vector2d b = preset.camera.Project({wall.x, wall.y, wall.z});
    const cv::Rect image(0, 0, gray.cols, gray.rows);
    const cv::Point pa(cvRound(a.x()), cvRound(a.y())), pb(cvRound(b.x()), cvRound(b.y()));
    if (!image.contains(pa) || !image.contains(pb)) continue;
    step += std::abs(gray.at<uchar>(pa) - gray.at<uchar>(pb));
    ++visible;
  }
  ASSERT_GE(visible, 3);
  EXPECT_LT(step / visible, 12.0) << "the grey step should be small";
  CeilingEstimate estimate;
  ASSERT_TRUE(DetectCeiling(frame.bgr, preset.camera, g, CeilingDetectorOptions(), &estimate).ok());
  ASSERT_TRUE(estimate.found) << estimate.reason;
  EXPECT_NEAR(estimate.height, preset.scene.ceiling_height, 0.03 * preset.scene.ceiling_height);
}

// A 3.4 m ceiling under a 16:9 image (the paper camera's rows cut to 236): each junction comes into
// view only a few metres ahead, so most of the searched samples (from 1 m) are out of the image.
TEST(CeilingDetectorTest, FindsAHighCeilingSeenOnlyFromAFewMetres) {
  int checked = 0;
  for (const auto& preset : synth::PaperPreset()) {
    if (preset.name.find("_E") == std::string::npos) continue;
    synth::SceneOptions options = preset.scene;
    options.ceiling_height = 3.4;
    const synth::CorridorScene scene = synth::BuildScene(options);
    Camera camera = preset.camera;
    camera.image_height = 236;
    camera.cy = 117.5;
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(scene, camera, preset.poses[4], &frame).ok());
    const CorridorGeometry& g = frame.truth;
    // The premise: the nearest point of either junction in view is at least 4 m ahead.
    const CorridorRotation<double> r(g.pitch, g.yaw);
    double nearest = 1e9;
    for (const double x : {-g.LeftDistance(), g.RightDistance()}) {
      for (double z = 1.0; z <= 30.0; z += 0.05) {
        const Vec3<double> p = r.ToCamera({x, g.camera_height - options.ceiling_height, z});
        const Eigen::Vector2d uv = camera.Project({p.x, p.y, p.z});
        if (p.z > 0 && uv.x() >= 0 && uv.x() < camera.image_width && uv.y() >= 0 &&
            uv.y() < camera.image_height) {
          nearest = std::min(nearest, z);
          break;
        }
      }
    }
    ASSERT_GT(nearest, 4.0) << preset.name;
    CeilingEstimate estimate;
    ASSERT_TRUE(DetectCeiling(frame.bgr, camera, g, CeilingDetectorOptions(), &estimate).ok());
    ASSERT_TRUE(estimate.found) << preset.name << ": " << estimate.reason;
    EXPECT_NEAR(estimate.height, options.ceiling_height, 0.03 * options.ceiling_height)
        << preset.name;
    // Each side's own line: judged on its samples in view, strong enough to be trusted, and never
    // weaker than counted over half of all samples. (Its height, chosen on half of all samples,
    // leans toward lower lines, which come into view nearer: within 5%, not 3%.)
    for (int side = 0; side < 2; ++side) {
      EXPECT_NEAR(estimate.side_height[side], options.ceiling_height,
                  0.05 * options.ceiling_height)
          << preset.name << " " << side;
      EXPECT_GE(estimate.side_visible_support[side], estimate.side_support[side]);
      EXPECT_GE(estimate.side_visible_support[side], CeilingDetectorOptions().min_support)
          << preset.name << " " << side;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

TEST(CeilingDetectorTest, NoCeilingInAFeaturelessUpperImage) {
  const Camera camera = synth::PaperCamera(0.66);
  cv::Mat image(camera.image_height, camera.image_width, CV_8UC3, cv::Scalar(180, 180, 180));
  cv::rectangle(image, cv::Rect(0, 200, camera.image_width, 160), cv::Scalar(60, 80, 120),
                cv::FILLED);
  CorridorGeometry g;
  g.width = 2.2;
  g.camera_height = 0.66;
  g.pitch = 0.05;
  CeilingEstimate estimate;
  ASSERT_TRUE(DetectCeiling(image, camera, g, CeilingDetectorOptions(), &estimate).ok());
  EXPECT_FALSE(estimate.found);
  EXPECT_FALSE(estimate.reason.empty());
}

TEST(CeilingDetectorTest, RejectsBadOptionsAndImages) {
  CeilingDetectorOptions o;
  o.max_height = 1.0;
  std::string why;
  EXPECT_FALSE(o.Check(&why));
  for (const double fraction : {0.0, 1.5, std::nan("")}) {
    CeilingDetectorOptions counted;
    counted.min_counted_fraction = fraction;
    EXPECT_FALSE(counted.Check(&why)) << fraction;
    EXPECT_NE(why.find("min_counted_fraction"), std::string::npos) << why;
  }
  CeilingEstimate estimate;
  CorridorGeometry g;
  EXPECT_EQ(DetectCeiling(cv::Mat(), synth::PaperCamera(0.66), g, CeilingDetectorOptions(), &estimate)
                .code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace corridor
