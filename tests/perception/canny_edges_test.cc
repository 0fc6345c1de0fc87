// CannyFromGradients against OpenCV's own cv::Canny on the same derivatives: random derivatives in
// a small range (many ties, every direction), the Sobel derivatives of a generated corridor, both
// magnitudes, thresholds that are not integers, and images of one row or column.
#include "kernels/canny_edges.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "synth/corridor_renderer.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

void ExpectSameAsOpenCv(const cv::Mat& dx, const cv::Mat& dy, double low, double high, bool l2,
                        const std::string& what) {
  cv::Mat expected, edges;
  cv::Canny(dx, dy, expected, low, high, l2);
  ASSERT_TRUE(CannyFromGradients(dx, dy, low, high, l2, &edges).ok()) << what;
  ASSERT_EQ(edges.size(), expected.size()) << what;
  ASSERT_EQ(edges.type(), CV_8UC1) << what;
  EXPECT_EQ(cv::countNonZero(edges != expected), 0)
      << what << ": " << cv::countNonZero(expected) << " OpenCV edges, "
      << cv::countNonZero(edges) << " here";
}

TEST(CannyEdgesTest, EqualsOpenCvOnRandomDerivatives) {
  cv::RNG rng(11);
  int with_edges = 0;
  for (const cv::Size size : {cv::Size(97, 61), cv::Size(1, 17), cv::Size(23, 1), cv::Size(2, 2),
                              cv::Size(640, 40)}) {
    for (int range : {3, 12, 60, 1020, 20000}) {
      cv::Mat dx(size, CV_16SC1), dy(size, CV_16SC1);
      rng.fill(dx, cv::RNG::UNIFORM, -range, range + 1);
      rng.fill(dy, cv::RNG::UNIFORM, -range, range + 1);
      for (bool l2 : {false, true}) {
        const double high = (l2 ? 0.9 : 1.2) * range, low = 0.45 * high;
        const std::string what = std::to_string(size.width) + "x" + std::to_string(size.height) +
                                 " range " + std::to_string(range) + (l2 ? " L2" : " L1");
        cv::Mat expected;
        cv::Canny(dx, dy, expected, low, high, l2);
        if (cv::countNonZero(expected) > 0) ++with_edges;
        ExpectSameAsOpenCv(dx, dy, low, high, l2, what);
        ExpectSameAsOpenCv(dx, dy, high, low, l2, what + " (thresholds swapped)");
      }
    }
  }
  EXPECT_GT(with_edges, 20);  // The comparison saw edges, not only empty maps.
}

TEST(CannyEdgesTest, EqualsOpenCvOnACorridorsSobelDerivatives) {
  const Camera camera = Camera::FromHorizontalFov(420, 360, 85.0 * M_PI / 180, 0.7);
  const synth::SceneOptions defaults;
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, defaults.width, defaults.ceiling_height, defaults.seed,
      synth::CameraPose{0.05, 0.03, 0.2, 0.7, 3.0}, 0.1);
  const cv::Mat& image = frame.bgr;
  ASSERT_FALSE(image.empty());
  cv::Mat grey, dx, dy;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  cv::Sobel(grey, dx, CV_16S, 1, 0, 3);
  cv::Sobel(grey, dy, CV_16S, 0, 1, 3);
  ExpectSameAsOpenCv(dx, dy, 20, 60, true, "corridor, L2 20/60");
  ExpectSameAsOpenCv(dx, dy, 40.5, 101.3, false, "corridor, L1 40.5/101.3");
  ExpectSameAsOpenCv(dx, dy, 0, 0, false, "corridor, zero thresholds");
}

// The largest derivatives, where OpenCV's int arithmetic overflows: by the header's rule the L2
// magnitude of (-32768, -32768) is 2^31 (capped at 2^31 - 1) and its L1 magnitude 65536, both
// above the highest thresholds, so each lone pixel (its neighbours zero) is an edge; (32767,
// -32768) likewise. Pixels at columns the row loops take in groups and one by one.
TEST(CannyEdgesTest, LoneExtremeDerivativesAreEdges) {
  for (bool l2 : {false, true}) {
    cv::Mat dx(9, 70, CV_16SC1, cv::Scalar(0)), dy(9, 70, CV_16SC1, cv::Scalar(0));
    const cv::Point at[] = {{5, 1}, {31, 3}, {37, 5}, {67, 7}};
    for (const cv::Point& p : at) {
      dx.at<int16_t>(p) = p.x == 37 ? 32767 : -32768;
      dy.at<int16_t>(p) = -32768;
    }
    const double high = l2 ? 32767 : 65534;
    cv::Mat edges;
    ASSERT_TRUE(CannyFromGradients(dx, dy, high, high, l2, &edges).ok());
    cv::Mat expected(dx.size(), CV_8UC1, cv::Scalar(0));
    for (const cv::Point& p : at) expected.at<uint8_t>(p) = 255;
    EXPECT_EQ(cv::countNonZero(edges != expected), 0) << (l2 ? "L2" : "L1");
  }
}

TEST(CannyEdgesTest, RejectsDerivativesOfTheWrongTypeOrSize) {
  cv::Mat edges;
  const cv::Mat a(4, 5, CV_16SC1, cv::Scalar(0)), b(5, 4, CV_16SC1, cv::Scalar(0));
  EXPECT_FALSE(CannyFromGradients(a, b, 10, 20, false, &edges).ok());
  EXPECT_FALSE(CannyFromGradients(cv::Mat(), cv::Mat(), 10, 20, false, &edges).ok());
  const cv::Mat f(4, 5, CV_32FC1, cv::Scalar(0));
  EXPECT_FALSE(CannyFromGradients(f, f, 10, 20, false, &edges).ok());
}

}  // namespace
}  // namespace corridor
