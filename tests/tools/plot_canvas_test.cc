#include "tools/eval/plot_canvas.h"

#include <gtest/gtest.h>

namespace corridor {
namespace {

TEST(NiceTicks, RoundSteps) {
  EXPECT_EQ(NiceTicks(0, 40, 10), (std::vector<double>{0, 5, 10, 15, 20, 25, 30, 35, 40}));
  const std::vector<double> ticks = NiceTicks(0, 0.23, 6);
  ASSERT_EQ(ticks.size(), 5u);  // 0, 0.05, ..., 0.2
  EXPECT_NEAR(ticks[1], 0.05, 1e-12);
  EXPECT_NEAR(NiceTicks(-7, 7, 4).front(), -5, 1e-12);
  EXPECT_TRUE(NiceTicks(1, 1, 5).empty());
}

TEST(PlotCanvas, MapsDataToThePlotAreaAndDraws) {
  PlotCanvas plot(400, 300, "title", "x", "y");
  plot.SetRange(0, 10, 0, 1);
  const cv::Point origin = plot.ToPixel(0, 0), corner = plot.ToPixel(10, 1);
  EXPECT_LT(origin.x, corner.x);
  EXPECT_GT(origin.y, corner.y);  // y grows upwards.
  EXPECT_GT(origin.x, 0);
  EXPECT_LT(corner.x, 400);
  plot.DrawAxes();
  const cv::Mat before = plot.image().clone();
  plot.Bar(4, 6, 0.5, cv::Scalar(255, 0, 0));
  EXPECT_EQ(plot.image().at<cv::Vec3b>(plot.ToPixel(5, 0.25)), cv::Vec3b(255, 0, 0));
  plot.Polyline({{1, 0.9}, {9, 0.9}}, cv::Scalar(0, 0, 255));
  EXPECT_EQ(plot.image().at<cv::Vec3b>(plot.ToPixel(5, 0.9)), cv::Vec3b(0, 0, 255));
  plot.CategoryLabels({"a very long scene name", "b", "c"});
  plot.Legend({{"series", cv::Scalar(0, 255, 0)}});
  EXPECT_GT(cv::norm(plot.image(), before, cv::NORM_L1), 0);
  EXPECT_EQ(plot.image().size(), cv::Size(400, 300));
}

TEST(PlotCanvas, DegenerateRangeDoesNotDivideByZero) {
  PlotCanvas plot(200, 150, "t", "x", "y");
  plot.SetRange(3, 3, 0, 0);
  const cv::Point p = plot.ToPixel(3, 0);
  EXPECT_GE(p.x, 0);
  EXPECT_LT(p.y, 150);
  plot.DrawAxes();
}

}  // namespace
}  // namespace corridor
