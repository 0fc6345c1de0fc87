// HalveToWidth: the halved image's size and the camera that matches it, checked against where
// cv::pyrDown itself puts a bright pixel (measured, not assumed); and the ceiling search at the
// halved resolution on a 1280x720 render, against the generator's ceiling height.
#include "perception/working_image.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "kernels/binomial_blur.h"
#include "perception/ceiling_detector.h"
#include "synth/corridor_renderer.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

TEST(WorkingImageTest, HalvesUntilItFitsAndScalesTheCamera) {
  Camera camera = Camera::FromHorizontalFov(1280, 720, 80.0 * M_PI / 180, 1.1);
  camera.cx = 650.25;
  camera.cy = 340.75;
  camera.distortion = {-0.12, 0.03, 0.001, -0.002, 0.0};
  const cv::Mat image(720, 1280, CV_8UC3, cv::Scalar(10, 20, 30));
  const WorkingImage work = HalveToWidth(image, camera, 400);
  EXPECT_EQ(work.scale, 4);  // 1280 -> 640 -> 320.
  EXPECT_EQ(work.bgr.cols, 320);
  EXPECT_EQ(work.bgr.rows, 180);
  EXPECT_EQ(work.camera.image_width, 320);
  EXPECT_EQ(work.camera.image_height, 180);
  // Where cv::pyrDown moves a pixel: the centroid of an impulse's response, halved twice.
  cv::Mat impulse = cv::Mat::zeros(64, 64, CV_32F);
  impulse.at<float>(37, 22) = 1.0f;  // Row 37, column 22.
  cv::Mat down;
  cv::pyrDown(impulse, down);
  cv::pyrDown(down, down);
  const cv::Moments m = cv::moments(down);
  const double x_ratio = (m.m10 / m.m00) / 22.0, y_ratio = (m.m01 / m.m00) / 37.0;
  ASSERT_NEAR(x_ratio, 0.25, 1e-6);  // Pixel i goes to i / 4, with no shift.
  ASSERT_NEAR(y_ratio, 0.25, 1e-6);
  // The scaled camera must see every point where the halved image shows it.
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0.3, -0.2, 2.0), Eigen::Vector3d(-1.1, 0.4, 3.5)}) {
    const Eigen::Vector2d full = camera.Distort(camera.Project(p));
    const Eigen::Vector2d halved = work.camera.Distort(work.camera.Project(p));
    EXPECT_NEAR(halved.x(), full.x() * x_ratio, 1e-6);
    EXPECT_NEAR(halved.y(), full.y() * y_ratio, 1e-6);
  }
}

TEST(WorkingImageTest, ANarrowEnoughImageIsLeftAlone) {
  const Camera camera = Camera::FromHorizontalFov(640, 480, 70.0 * M_PI / 180, 1.0);
  const cv::Mat image(480, 640, CV_8UC3, cv::Scalar(1, 2, 3));
  for (const int max_width : {0, 640, 2000}) {
    const WorkingImage work = HalveToWidth(image, camera, max_width);
    EXPECT_EQ(work.scale, 1);
    EXPECT_EQ(work.bgr.data, image.data);  // The same pixels, not a copy.
    EXPECT_EQ(work.camera.fx, camera.fx);
    EXPECT_EQ(work.camera.cx, camera.cx);
  }
}

// PyrDown against OpenCV's own pyrDown: the same pixels for every size (odd, even, the smallest
// it handles and smaller), channel count, a view into a larger image, and a float image (which
// OpenCV handles).
TEST(WorkingImageTest, PyrDownGivesCvPyrDownsPixels) {
  cv::RNG rng(17);
  for (const int channels : {1, 3, 4}) {
    for (const cv::Size size : {cv::Size(1280, 720), cv::Size(641, 361), cv::Size(7, 5),
                                cv::Size(3, 3), cv::Size(4, 3), cv::Size(2, 2), cv::Size(1, 5)}) {
      cv::Mat image(size, CV_8UC(channels));
      rng.fill(image, cv::RNG::UNIFORM, 0, 256);
      cv::Mat ours, theirs;
      PyrDown(image, &ours);
      cv::pyrDown(image, theirs);
      ASSERT_EQ(ours.size(), theirs.size()) << size << " x" << channels;
      ASSERT_EQ(ours.type(), theirs.type());
      EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0.0) << size << " x" << channels;
    }
  }
  cv::Mat big(100, 90, CV_8UC3);
  rng.fill(big, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat view = big(cv::Rect(5, 7, 61, 40));
  cv::Mat ours, theirs;
  PyrDown(view, &ours);
  cv::pyrDown(view, theirs);
  EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0.0);
  cv::Mat real(31, 29, CV_32FC3);
  rng.fill(real, cv::RNG::UNIFORM, 0.0, 1.0);
  PyrDown(real, &ours);
  cv::pyrDown(real, theirs);
  EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0.0);
  // In place, as HalveToWidth calls it.
  cv::Mat same = big.clone();
  PyrDown(same, &same);
  cv::pyrDown(big, theirs);
  EXPECT_EQ(cv::norm(same, theirs, cv::NORM_INF), 0.0);
}

// The recoverer searches the ceiling of images wider than 640 px at half resolution (its
// search_max_width): there it still lands within 3% of the truth.
// PyrDown with the image's top rows already blurred (BinomialBlur, as the ceiling search leaves
// them): cv::pyrDown's pixels for every count of blurred rows (none, odd, even, all), sizes odd
// and even, 1, 3 and 4 channels; a blur of another width is ignored.
TEST(WorkingImageTest, PyrDownFromBlurredRowsGivesCvPyrDownsPixels) {
  cv::RNG rng(23);
  for (const int channels : {1, 3, 4}) {
    for (const cv::Size size : {cv::Size(640, 480), cv::Size(641, 361), cv::Size(37, 9)}) {
      cv::Mat image(size, CV_8UC(channels));
      rng.fill(image, cv::RNG::UNIFORM, 0, 256);
      cv::Mat theirs;
      cv::pyrDown(image, theirs);
      for (const int rows : {1, 2, 5, size.height / 2, size.height / 2 + 1, size.height}) {
        cv::Mat blurred;
        ASSERT_TRUE(BinomialBlur(image, 0, rows, 5, &blurred).ok());
        cv::Mat ours;
        PyrDown(image, &ours, &blurred);
        ASSERT_EQ(ours.size(), theirs.size());
        EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0.0)
            << size << " x" << channels << ", " << rows << " rows blurred";
      }
      // A blur that is not of this image's width is not used.
      cv::Mat narrow;
      ASSERT_TRUE(BinomialBlur(image.colRange(0, size.width - 2), 0, 4, 5, &narrow).ok());
      cv::Mat ours;
      PyrDown(image, &ours, &narrow);
      EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0.0) << size << " x" << channels;
    }
  }
}

TEST(WorkingImageTest, TheCeilingOfALargeFrameIsFoundAtHalfResolution) {
  const Camera camera = Camera::FromHorizontalFov(1280, 720, 85.0 * M_PI / 180, 0.7);
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, 2.2, 2.8, 5, synth::CameraPose{0.06, 0.04, 0.15, 0.7, 3.0});
  ASSERT_FALSE(frame.bgr.empty());
  const WorkingImage work = HalveToWidth(frame.bgr, camera, 640);
  ASSERT_EQ(work.scale, 2);
  CeilingEstimate estimate;
  ASSERT_TRUE(
      DetectCeiling(work.bgr, work.camera, frame.truth, CeilingDetectorOptions(), &estimate).ok());
  ASSERT_TRUE(estimate.found) << estimate.reason;
  EXPECT_NEAR(estimate.height, frame.truth.ceiling_height, 0.03 * frame.truth.ceiling_height);
}

}  // namespace
}  // namespace corridor
