#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

namespace corridor {

// A tiny 2-D chart drawn with OpenCV: white canvas, title, axes with ticks, tick labels, grid
// and axis labels. Data coordinates map linearly to the plot area.
class PlotCanvas {
 public:
  PlotCanvas(int width, int height, const std::string& title, const std::string& x_label,
             const std::string& y_label);

  // The data range shown; an empty range is widened so that nothing divides by zero.
  void SetRange(double x_min, double x_max, double y_min, double y_max);
  // Frame, grid and ticks. Numeric x ticks unless `x_ticks` is false (categories instead).
  void DrawAxes(bool x_ticks = true);
  // Labels centred at x = 0, 1, ..., n-1 (rotated when they do not fit side by side).
  void CategoryLabels(const std::vector<std::string>& labels);
  // A polyline through the points, with a dot at each.
  void Polyline(const std::vector<cv::Point2d>& points, const cv::Scalar& color);
  // A filled bar from y = 0 up to y between x0 and x1.
  void Bar(double x0, double x1, double y, const cv::Scalar& color);
  // Coloured boxes with names in the top-right corner.
  void Legend(const std::vector<std::pair<std::string, cv::Scalar>>& entries);
  // Centred grey text in the plot area (e.g. "no data").
  void Message(const std::string& text);

  cv::Point ToPixel(double x, double y) const;
  const cv::Mat& image() const { return image_; }

 private:
  cv::Mat image_;
  cv::Rect area_;  // The plot area in pixels.
  double x_min_ = 0, x_max_ = 1, y_min_ = 0, y_max_ = 1;
  std::string x_label_, y_label_;
};

// About `target` round tick values (steps of 1, 2 or 5 times a power of ten) in [lo, hi].
std::vector<double> NiceTicks(double lo, double hi, int target);

}  // namespace corridor
