// MeanColourAtRadii against the scalar sum it replaces (ColourAt of each point, summed as doubles
// in order, divided with cv::Vec3d's division): bit for bit, on random rays through a random image
// and its lower half, with points beyond every border, on exact halves, and not numbers.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "kernels/line_colour.h"
#include "perception/band_profile.h"

namespace corridor {
namespace {

cv::Vec3d Reference(const cv::Mat& roi, int roi_top, double x0, double y0, double dx, double dy,
                    const std::vector<double>& radii) {
  cv::Vec3d sum(0, 0, 0);
  for (const double r : radii) {
    sum += ColourAt(roi, roi_top, Eigen::Vector2d(x0 + r * dx, y0 + r * dy));
  }
  return sum / static_cast<double>(radii.size());
}

TEST(LineColourTest, EqualsTheScalarSumBitForBit) {
  std::mt19937 rng(11);
  cv::Mat image(120, 160, CV_8UC3);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(256));
  std::uniform_real_distribution<double> coordinate(-60, 220), angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> radius(0, 150);
  std::uniform_int_distribution<int> count(1, 53);
  for (const int roi_top : {0, 60}) {
    const cv::Mat roi = image.rowRange(roi_top, image.rows);
    for (int trial = 0; trial < 2000; ++trial) {
      const double x0 = coordinate(rng), y0 = coordinate(rng), a = angle(rng);
      std::vector<double> radii(static_cast<size_t>(count(rng)));
      for (double& r : radii) r = radius(rng);
      // Some rays along whole and half pixels: the rounding's ties.
      const bool ties = trial % 4 == 0;
      const double x = ties ? std::round(2 * x0) / 2 : x0, y = ties ? std::round(2 * y0) / 2 : y0;
      const double dx = ties ? 0.5 : std::cos(a), dy = ties ? -0.5 : std::sin(a);
      if (ties) {
        for (double& r : radii) r = std::round(r);
      }
      const cv::Vec3d got = MeanColourAtRadii(roi, roi_top, x, y, dx, dy, radii.data(),
                                              static_cast<int>(radii.size()));
      const cv::Vec3d want = Reference(roi, roi_top, x, y, dx, dy, radii);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(got[c], want[c]) << trial << " " << c;
    }
  }
}

TEST(LineColourTest, AViewOfSomeColumnsIsReadThroughItsRowStep) {
  std::mt19937 rng(5);
  cv::Mat image(90, 130, CV_8UC3);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(256));
  // Rows 30-89, columns 10-109: rows a step longer than their pixels, the last one ending before
  // the image's data does.
  const cv::Mat roi = image(cv::Rect(10, 30, 100, 60));
  std::uniform_real_distribution<double> coordinate(-20, 140), angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> radius(0, 120);
  for (int trial = 0; trial < 500; ++trial) {
    const double x0 = coordinate(rng), y0 = 30 + coordinate(rng), a = angle(rng);
    std::vector<double> radii(24);
    for (double& r : radii) r = radius(rng);
    const cv::Vec3d got = MeanColourAtRadii(roi, 30, x0, y0, std::cos(a), std::sin(a),
                                            radii.data(), static_cast<int>(radii.size()));
    const cv::Vec3d want = Reference(roi, 30, x0, y0, std::cos(a), std::sin(a), radii);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(got[c], want[c]) << trial << " " << c;
  }
}

TEST(LineColourTest, PointsFarOutsideOrNotNumbersAreClampedAsTheScalarCodeDoes) {
  cv::Mat image(40, 50, CV_8UC3);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(256));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> radii = {0, 1, 2e9, -3e9, 5, 6, 7, nan, 9};
  for (const double dx : {1.0, -1.0, nan}) {
    const cv::Vec3d got = MeanColourAtRadii(image, 0, 10, 20, dx, 0.5, radii.data(),
                                            static_cast<int>(radii.size()));
    const cv::Vec3d want = Reference(image, 0, 10, 20, dx, 0.5, radii);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(got[c], want[c]) << dx << " " << c;
  }
}

}  // namespace
}  // namespace corridor
