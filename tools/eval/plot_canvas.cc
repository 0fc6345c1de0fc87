#include "tools/eval/plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTickScale = 0.42;
const cv::Scalar kInk(40, 40, 40);
const cv::Scalar kGrid(225, 225, 225);

std::string TickText(double value, double step) {
  char text[32];
  const int decimals = step >= 1 ? 0 : std::min(6, static_cast<int>(std::ceil(-std::log10(step))));
  std::snprintf(text, sizeof(text), "%.*f", decimals, std::abs(value) < step * 1e-6 ? 0.0 : value);
  return text;
}

cv::Size TextSize(const std::string& text, double scale) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, 1, &baseline);
}

// Draws text rotated by 90 degrees (reading bottom to top) with its top-left corner at `at`.
void PutVertical(cv::Mat* image, const std::string& text, cv::Point at, double scale) {
  const cv::Size size = TextSize(text, scale);
  cv::Mat strip(size.height + 6, size.width + 2, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(strip, text, cv::Point(1, size.height + 2), kFont, scale, kInk, 1, cv::LINE_AA);
  cv::Mat rotated;
  cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  const cv::Rect target = cv::Rect(at, rotated.size()) & cv::Rect(0, 0, image->cols, image->rows);
  if (target.area() > 0) {
    rotated(cv::Rect(0, 0, target.width, target.height)).copyTo((*image)(target));
  }
}

}  // namespace

std::vector<double> NiceTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || target < 1) return ticks;
  const double raw = (hi - lo) / target;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * power;
    if (step >= raw) break;
  }
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) {
    ticks.push_back(v);
  }
  return ticks;
}

PlotCanvas::PlotCanvas(int width, int height, const std::string& title, const std::string& x_label,
                       const std::string& y_label)
    : image_(height, width, CV_8UC3, cv::Scalar(255, 255, 255)),
      area_(78, 44, std::max(10, width - 78 - 24), std::max(10, height - 44 - 62)),
      x_label_(x_label),
      y_label_(y_label) {
  const cv::Size size = TextSize(title, 0.6);
  cv::putText(image_, title, cv::Point(std::max(4, (width - size.width) / 2), 28), kFont, 0.6, kInk,
              1, cv::LINE_AA);
}

void PlotCanvas::SetRange(double x_min, double x_max, double y_min, double y_max) {
  if (!(x_max > x_min)) x_max = x_min + 1;
  if (!(y_max > y_min)) y_max = y_min + 1;
  x_min_ = x_min;
  x_max_ = x_max;
  y_min_ = y_min;
  y_max_ = y_max;
}

cv::Point PlotCanvas::ToPixel(double x, double y) const {
  const double u = area_.x + (x - x_min_) / (x_max_ - x_min_) * area_.width;
  const double v = area_.y + area_.height - (y - y_min_) / (y_max_ - y_min_) * area_.height;
  return {cvRound(u), cvRound(v)};
}

void PlotCanvas::DrawAxes(bool x_ticks) {
  const std::vector<double> yt = NiceTicks(y_min_, y_max_, 6);
  const double y_step = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (double y : yt) {
    const cv::Point p = ToPixel(x_min_, y);
    cv::line(image_, p, cv::Point(area_.br().x, p.y), kGrid, 1);
    cv::line(image_, p, p - cv::Point(5, 0), kInk, 1);
    const std::string text = TickText(y, y_step);
    const cv::Size size = TextSize(text, kTickScale);
    cv::putText(image_, text, cv::Point(p.x - 8 - size.width, p.y + size.height / 2), kFont,
                kTickScale, kInk, 1, cv::LINE_AA);
  }
  if (x_ticks) {
    const std::vector<double> xt = NiceTicks(x_min_, x_max_, 10);
    const double x_step = xt.size() > 1 ? xt[1] - xt[0] : 1.0;
    for (double x : xt) {
      const cv::Point p = ToPixel(x, y_min_);
      cv::line(image_, cv::Point(p.x, area_.y), p, kGrid, 1);
      cv::line(image_, p, p + cv::Point(0, 5), kInk, 1);
      const std::string text = TickText(x, x_step);
      const cv::Size size = TextSize(text, kTickScale);
      cv::putText(image_, text, cv::Point(p.x - size.width / 2, p.y + 10 + size.height), kFont,
                  kTickScale, kInk, 1, cv::LINE_AA);
    }
  }
  cv::rectangle(image_, area_, kInk, 1);
  const cv::Size x_size = TextSize(x_label_, 0.5);
  cv::putText(image_, x_label_,
              cv::Point(area_.x + (area_.width - x_size.width) / 2, image_.rows - 12), kFont, 0.5,
              kInk, 1, cv::LINE_AA);
  const cv::Size y_size = TextSize(y_label_, 0.5);
  PutVertical(&image_, y_label_,
              cv::Point(4, area_.y + std::max(0, (area_.height - y_size.width) / 2)), 0.5);
}

void PlotCanvas::CategoryLabels(const std::vector<std::string>& labels) {
  if (labels.empty()) return;
  int widest = 0;
  for (const auto& l : labels) widest = std::max(widest, TextSize(l, kTickScale).width);
  const double slot = static_cast<double>(area_.width) / labels.size();
  const bool rotate = widest + 6 > slot;
  for (size_t i = 0; i < labels.size(); ++i) {
    const cv::Point p = ToPixel(static_cast<double>(i), y_min_);
    const cv::Size size = TextSize(labels[i], kTickScale);
    if (rotate) {
      // Rotated labels would run into the axis label: shorten them to the room below the axis.
      std::string text = labels[i];
      while (text.size() > 3 && TextSize(text, kTickScale).width > 40) text.pop_back();
      PutVertical(&image_, text, cv::Point(p.x - size.height / 2 - 3, p.y + 4), kTickScale);
    } else {
      cv::putText(image_, labels[i], cv::Point(p.x - size.width / 2, p.y + 10 + size.height), kFont,
                  kTickScale, kInk, 1, cv::LINE_AA);
    }
  }
}

void PlotCanvas::Polyline(const std::vector<cv::Point2d>& points, const cv::Scalar& color) {
  std::vector<cv::Point> pixels;
  for (const auto& p : points) pixels.push_back(ToPixel(p.x, p.y));
  if (pixels.size() > 1) cv::polylines(image_, pixels, false, color, 2, cv::LINE_AA);
  for (const auto& p : pixels) cv::circle(image_, p, 3, color, cv::FILLED, cv::LINE_AA);
}

void PlotCanvas::Bar(double x0, double x1, double y, const cv::Scalar& color) {
  const cv::Point a = ToPixel(x0, std::max(y_min_, 0.0)), b = ToPixel(x1, y);
  const cv::Rect bar = cv::Rect(a, b) & area_;
  cv::rectangle(image_, bar, color, cv::FILLED);
  cv::rectangle(image_, bar, kInk, 1);
}

void PlotCanvas::Legend(const std::vector<std::pair<std::string, cv::Scalar>>& entries) {
  int y = area_.y + 8;
  for (const auto& [name, color] : entries) {
    const cv::Size size = TextSize(name, kTickScale);
    const int x = area_.br().x - size.width - 28;
    cv::rectangle(image_, cv::Rect(x - 4, y - 2, size.width + 30, 18), cv::Scalar(255, 255, 255),
                  cv::FILLED);
    cv::rectangle(image_, cv::Rect(x, y + 2, 14, 10), color, cv::FILLED);
    cv::putText(image_, name, cv::Point(x + 20, y + 12), kFont, kTickScale, kInk, 1, cv::LINE_AA);
    y += 20;
  }
}

void PlotCanvas::Message(const std::string& text) {
  const cv::Size size = TextSize(text, 0.6);
  cv::putText(image_, text,
              cv::Point(area_.x + (area_.width - size.width) / 2, area_.y + area_.height / 2),
              kFont, 0.6, cv::Scalar(150, 150, 150), 1, cv::LINE_AA);
}

}  // namespace corridor
