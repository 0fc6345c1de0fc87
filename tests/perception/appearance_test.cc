// The floor-boundary cues: Lab of sampled pixels against OpenCV's whole-image conversion, and the
// boundary score and the band contrast on painted floor/wall images.
#include "perception/appearance.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

TEST(AppearanceTest, SampledLabEqualsTheWholeImageConversion) {
  cv::Mat image(97, 131, CV_8UC3);
  cv::RNG(11).fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::Mat lab;
  cv::cvtColor(image, lab, cv::COLOR_BGR2Lab);
  std::vector<cv::Point> where;
  std::vector<cv::Vec3b> bgr;
  cv::RNG pick(12);
  for (int k = 0; k < 500; ++k) {
    where.emplace_back(pick.uniform(0, image.cols), pick.uniform(0, image.rows));
    bgr.push_back(image.at<cv::Vec3b>(where.back()));
  }
  const std::vector<cv::Vec3b> sampled = BgrToLab(bgr);
  ASSERT_EQ(sampled.size(), where.size());
  for (size_t k = 0; k < where.size(); ++k) {
    EXPECT_EQ(sampled[k], lab.at<cv::Vec3b>(where[k])) << where[k];
  }
  EXPECT_TRUE(BgrToLab({}).empty());
}

// The floor's colour: the per-channel median (the middle of the sorted values) of the Lab pixels
// sampled (every second pixel of every second row) in the bottom 12% of the image's rows and the
// middle 30% of its columns, computed here by sorting OpenCV's conversion of the whole image.
TEST(AppearanceTest, FloorColourIsTheWindowsPerChannelMedian) {
  for (const int seed : {3, 4, 5}) {
    cv::Mat image(120, 90, CV_8UC3);
    cv::RNG(seed).fill(image, cv::RNG::UNIFORM, 0, 256);
    const int roi_top = 40;
    const cv::Mat roi = image.rowRange(roi_top, image.rows);
    cv::Mat lab;
    cv::cvtColor(roi, lab, cv::COLOR_BGR2Lab);
    const int v0 = static_cast<int>(0.88 * image.rows) - roi_top;
    const int u0 = static_cast<int>(0.35 * image.cols), u1 = static_cast<int>(0.65 * image.cols);
    std::vector<float> channel[3];
    for (int v = v0; v < roi.rows; v += 2) {
      for (int u = u0; u < u1; u += 2) {
        for (int c = 0; c < 3; ++c) channel[c].push_back(lab.at<cv::Vec3b>(v, u)[c]);
      }
    }
    const FloorAppearance floor = SampleFloor(roi, roi_top);
    for (int c = 0; c < 3; ++c) {
      std::sort(channel[c].begin(), channel[c].end());
      EXPECT_EQ(floor.lab[c], channel[c][channel[c].size() / 2]) << "seed " << seed << " c " << c;
    }
  }
}

// A grey wall above row 60 and a brown floor below it; the ROI starts at row 40.
TEST(AppearanceTest, TheFloorEdgeScoresHighAndLinesInsideOneSurfaceLow) {
  const cv::Scalar wall(200, 200, 200), floor_bgr(40, 90, 150);
  cv::Mat image(160, 200, CV_8UC3, wall);
  image.rowRange(60, 160).setTo(floor_bgr);
  const int roi_top = 40;
  const cv::Mat roi = image.rowRange(roi_top, image.rows);
  const FloorAppearance floor = SampleFloor(roi, roi_top);
  // The floor colour, converted on its own by OpenCV.
  cv::Mat one(1, 1, CV_8UC3, floor_bgr), one_lab;
  cv::cvtColor(one, one_lab, cv::COLOR_BGR2Lab);
  const cv::Vec3b expected = one_lab.at<cv::Vec3b>(0, 0);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(floor.lab[c], expected[c]);
  EXPECT_EQ(floor.spread, 1.0f);
  const auto horizontal = [](double v) {
    return LineThrough(Eigen::Vector2d(20, v), Eigen::Vector2d(180, v));
  };
  EXPECT_GT(BoundaryScore(roi, floor, horizontal(59.5), roi_top), 0.95);  // The floor's edge.
  EXPECT_LT(BoundaryScore(roi, floor, horizontal(120), roi_top), 0.05);   // Inside the floor.
  EXPECT_LT(BoundaryScore(roi, floor, horizontal(48), roi_top), 0.05);    // On the wall.
  // Entirely above the ROI: no usable sample.
  EXPECT_EQ(BoundaryScore(roi, floor, horizontal(10), roi_top), 0.0);
}

// A 1280-pixel image searched at half resolution (scale 2): a grout line inside the floor, a
// light 2 px line with a 3 px dark shadow above it, 20 px below the junction. Probes 4 px from
// the grout line's lower edge land in its shadow, which looks like the wall above a junction;
// probes 4 scale px away see floor on both sides. The junction scores high at either scale.
TEST(AppearanceTest, ProbesScaleWithTheWorkingResolution) {
  const cv::Scalar wall(200, 200, 200), floor_bgr(40, 90, 150);
  const cv::Scalar shadow(20, 30, 40), grout(170, 180, 190);
  cv::Mat image(200, 200, CV_8UC3, wall);
  image.rowRange(60, 200).setTo(floor_bgr);
  image.rowRange(77, 80).setTo(shadow);
  image.rowRange(80, 82).setTo(grout);
  const int roi_top = 40;
  const cv::Mat roi = image.rowRange(roi_top, image.rows);
  const FloorAppearance floor = SampleFloor(roi, roi_top);
  const auto horizontal = [](double v) {
    return LineThrough(Eigen::Vector2d(20, v), Eigen::Vector2d(180, v));
  };
  // The grout's lower edge (row 81.5): 4 px above is row 77.5, the shadow.
  EXPECT_GT(BoundaryScore(roi, floor, horizontal(81.5), roi_top, 1), 0.95);
  EXPECT_LT(BoundaryScore(roi, floor, horizontal(81.5), roi_top, 2), 0.05);
  EXPECT_GT(BoundaryScore(roi, floor, horizontal(59.5), roi_top, 1), 0.95);
  EXPECT_GT(BoundaryScore(roi, floor, horizontal(59.5), roi_top, 2), 0.95);
  // Scale 2 probes 8 px away with 3x3 patches 2 px apart: the wall 2-10 px above the junction.
  EXPECT_LT(BoundaryScore(roi, floor, horizontal(52.5), roi_top, 2), 0.05);  // On the wall.
}

// A vertical line's normal points right: the floor must be on its right, the wall on its left.
TEST(AppearanceTest, AVerticalBoundaryComparesItsLeftAndRightSides) {
  const cv::Scalar wall(200, 200, 200), floor_bgr(40, 90, 150);
  cv::Mat image(160, 200, CV_8UC3, wall);
  image.colRange(100, 200).setTo(floor_bgr);
  cv::Mat one(1, 1, CV_8UC3, floor_bgr), one_lab;
  cv::cvtColor(one, one_lab, cv::COLOR_BGR2Lab);
  FloorAppearance floor;
  floor.lab = one_lab.at<cv::Vec3b>(0, 0);
  const MergedLine boundary = LineThrough(Eigen::Vector2d(99.5, 10), Eigen::Vector2d(99.5, 150));
  ASSERT_GT(boundary.line.x(), 0.99);  // Normal (1, 0).
  EXPECT_GT(BoundaryScore(image, floor, boundary, 0), 0.95);
  const MergedLine inside = LineThrough(Eigen::Vector2d(150, 10), Eigen::Vector2d(150, 150));
  EXPECT_LT(BoundaryScore(image, floor, inside, 0), 0.05);
}

// 8-bit Lab of one BGR colour, by OpenCV's whole-image conversion.
cv::Vec3f LabOf(const cv::Scalar& bgr) {
  cv::Mat one(1, 1, CV_8UC3, bgr), lab;
  cv::cvtColor(one, lab, cv::COLOR_BGR2Lab);
  return lab.at<cv::Vec3b>(0, 0);
}

// A wall above row 60, a 12-row band (rows 60-71), a floor below: the band contrast of the band's
// two edges is the Lab distance of the band's colour from the floor's, lightness weighted a quarter
// (appearance.h), over the floor's spread (1 on a uniform floor).
TEST(AppearanceTest, TheBandBetweenTwoLinesIsComparedWithTheFloorBelowIt) {
  const cv::Scalar wall(200, 200, 200), floor_bgr(40, 90, 150);
  const auto contrast_of = [&](const cv::Scalar& band, double upper_v, double lower_v) {
    cv::Mat image(160, 200, CV_8UC3, wall);
    image.rowRange(60, 72).setTo(band);
    image.rowRange(72, 160).setTo(floor_bgr);
    const int roi_top = 40;
    const cv::Mat roi = image.rowRange(roi_top, image.rows);
    const FloorAppearance floor = SampleFloor(roi, roi_top);
    EXPECT_EQ(floor.spread, 1.0f);
    const MergedLine upper = LineThrough(Eigen::Vector2d(10, upper_v), Eigen::Vector2d(190, upper_v));
    const MergedLine lower = LineThrough(Eigen::Vector2d(20, lower_v), Eigen::Vector2d(180, lower_v));
    return BandContrast(roi, floor, upper, lower, roi_top);
  };
  const cv::Scalar baseboard(90, 90, 90);
  const cv::Vec3f d = LabOf(baseboard) - LabOf(floor_bgr);
  const double expected = std::sqrt(0.25 * (100.0 / 255) * (100.0 / 255) * d[0] * d[0] +
                                    d[1] * d[1] + d[2] * d[2]);
  ASSERT_GT(expected, 20.0);
  EXPECT_NEAR(contrast_of(baseboard, 59.5, 71.5), expected, 0.01 * expected);
  // The same band painted floor (a grout line below the junction): no contrast.
  EXPECT_NEAR(contrast_of(floor_bgr, 59.5, 71.5), 0.0, 1e-6);
  // Lines closer than 4 px, or lower not below upper: no band to measure.
  EXPECT_EQ(contrast_of(baseboard, 68.5, 71.5), -1.0);
  EXPECT_EQ(contrast_of(baseboard, 71.5, 59.5), -1.0);
}

// A band painted one colour has no fade; a band that ramps linearly from the wall's colour at its
// top to the floor's at its foot (a satin floor's reflection) changes between its quarter and
// three-quarter rows by as much as its middle differs from the floor: a fade of 1.
TEST(AppearanceTest, ABandsFadeFromTopToFootAgainstItsStepToTheFloor) {
  const cv::Scalar wall(200, 200, 200), floor_bgr(40, 90, 150);
  const auto fade_of = [&](bool ramp) {
    cv::Mat image(160, 200, CV_8UC3, wall);
    for (int v = 60; v < 84; ++v) {
      const double t = ramp ? (v - 60 + 0.5) / 24.0 : 0.3;  // 0 at the top, 1 at the foot.
      image.row(v).setTo(wall * (1 - t) + floor_bgr * t);
    }
    image.rowRange(84, 160).setTo(floor_bgr);
    const MergedLine upper = LineThrough(Eigen::Vector2d(10, 59.5), Eigen::Vector2d(190, 59.5));
    const MergedLine lower = LineThrough(Eigen::Vector2d(20, 83.5), Eigen::Vector2d(180, 83.5));
    return BandFade(image, upper, lower, 0);
  };
  EXPECT_NEAR(fade_of(false), 0.0, 1e-6);
  // Lab is not linear in BGR: the ramp's two halves differ a little in Lab length.
  EXPECT_NEAR(fade_of(true), 1.0, 0.2);
}

}  // namespace
}  // namespace corridor
