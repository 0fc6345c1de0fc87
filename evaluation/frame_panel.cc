#include "evaluation/frame_panel.h"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "corridor_depth/visualization.h"

namespace corridor {
namespace {

constexpr int kTitleHeight = 22;
const cv::Scalar kMissingColor(70, 70, 70);  // Ground truth without a prediction.

void PutText(cv::Mat* image, const std::string& text, cv::Point origin, double scale) {
  cv::putText(*image, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 3,
              cv::LINE_AA);
  cv::putText(*image, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(255, 255, 255), 1,
              cv::LINE_AA);
}

// Breaks `text` at spaces (or anywhere, for long words) into lines at most `width` pixels wide.
std::vector<std::string> WrapText(const std::string& text, int width, double scale) {
  std::vector<std::string> lines(1);
  int baseline = 0;
  const auto fits = [&](const std::string& line) {
    return cv::getTextSize(line, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width <= width;
  };
  for (char c : text) {
    if (c == '\n') {
      lines.emplace_back();
      continue;
    }
    lines.back() += c;
    if (fits(lines.back())) continue;
    const size_t space = lines.back().rfind(' ');
    std::string rest(1, c);
    if (space != std::string::npos && space > 0) {
      rest = lines.back().substr(space + 1);
      lines.back().erase(space);
    } else {
      lines.back().pop_back();
    }
    lines.push_back(rest);
  }
  return lines;
}

// The panel with a title strip above it.
cv::Mat WithTitle(const cv::Mat& panel, const std::string& title) {
  cv::Mat out(panel.rows + kTitleHeight, panel.cols, CV_8UC3, cv::Scalar(40, 40, 40));
  panel.copyTo(out(cv::Rect(0, kTitleHeight, panel.cols, panel.rows)));
  cv::putText(out, title, cv::Point(4, kTitleHeight - 7), cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  return out;
}

cv::Mat ColorizeError(const cv::Mat& error, const cv::Mat& gt, const cv::Mat& pred,
                      double max_error) {
  cv::Mat scaled;
  error.convertTo(scaled, CV_8U, 255.0 / max_error);
  cv::Mat color;
  cv::applyColorMap(scaled, color, cv::COLORMAP_INFERNO);
  color.setTo(cv::Scalar(0, 0, 0), gt <= 0);
  color.setTo(kMissingColor, (gt > 0) & ~(pred > 0));
  return color;
}

cv::Mat Blank(const cv::Size& size, const std::string& text) {
  cv::Mat out(size, CV_8UC3, cv::Scalar(0, 0, 0));
  PutText(&out, text, cv::Point(8, size.height / 2), 0.5);
  return out;
}

}  // namespace

cv::Mat AbsoluteErrorMap(const cv::Mat& pred, const cv::Mat& gt) {
  cv::Mat error = cv::Mat::zeros(gt.size(), CV_32F);
  if (pred.size() != gt.size() || pred.type() != CV_32F || gt.type() != CV_32F) return error;
  cv::Mat diff = cv::abs(pred - gt);
  diff.copyTo(error, (pred > 0) & (gt > 0));
  return error;
}

cv::Mat ErrorColorBar(int height, double max_error) {
  const int bar_width = 16, label_width = 52;
  cv::Mat ramp(height, 1, CV_8U);
  for (int v = 0; v < height; ++v) {
    ramp.at<uchar>(v, 0) = cv::saturate_cast<uchar>(255.0 * (height - 1 - v) / (height - 1.0));
  }
  cv::Mat colors;
  cv::applyColorMap(ramp, colors, cv::COLORMAP_INFERNO);
  cv::Mat bar = cv::Mat::zeros(height, bar_width + label_width, CV_8UC3);
  cv::resize(colors, bar(cv::Rect(0, 0, bar_width, height)), cv::Size(bar_width, height), 0, 0,
             cv::INTER_NEAREST);
  for (int i = 0; i <= 4; ++i) {
    const int v = cvRound((height - 1) * (1.0 - i / 4.0));
    char label[32];
    std::snprintf(label, sizeof(label), "%.2fm", max_error * i / 4.0);
    cv::putText(bar, label, cv::Point(bar_width + 3, std::clamp(v + 4, 10, height - 2)),
                cv::FONT_HERSHEY_SIMPLEX, 0.38, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  }
  return bar;
}

cv::Mat MakeEvalPanel(const cv::Mat& bgr, const RecoverDepthResult& result, const cv::Mat& pred,
                      const cv::Mat& gt, const EvalPanelScales& scales,
                      const std::string& caption) {
  const cv::Size size = bgr.size();
  cv::Mat lines = DrawJunctions(bgr, result.junctions);
  const std::vector<std::string> caption_lines = WrapText(caption, lines.cols - 12, 0.42);
  for (size_t i = 0; i < caption_lines.size() && i < 4; ++i) {
    PutText(&lines, caption_lines[i], cv::Point(6, 16 + 16 * static_cast<int>(i)), 0.42);
  }
  const bool have_pred = !pred.empty() && pred.size() == size;
  const bool have_gt = !gt.empty() && gt.size() == size;
  cv::Mat pred_color = have_pred ? ColorizeDepth(pred, scales.max_depth) : Blank(size, "no depth");
  cv::Mat gt_color = have_gt ? ColorizeDepth(gt, scales.max_depth)
                             : Blank(size, gt.empty() ? "no ground truth" : "size mismatch");
  cv::Mat error_color;
  if (have_gt) {
    const cv::Mat p = have_pred ? pred : cv::Mat::zeros(size, CV_32F);
    error_color = ColorizeError(AbsoluteErrorMap(p, gt), gt, p, scales.max_error);
  } else {
    error_color = Blank(size, "no error map");
  }
  const cv::Mat depth_bar = DepthColorBar(size.height, scales.max_depth);
  const cv::Mat error_bar = ErrorColorBar(size.height, scales.max_error);
  return HorizontalConcat(
      {WithTitle(lines, "input + junction lines"), WithTitle(pred_color, "predicted depth"),
       WithTitle(gt_color, "ground truth"), WithTitle(depth_bar, "depth"),
       WithTitle(error_color, "|pred - gt| (grey: no prediction)"), WithTitle(error_bar, "error")});
}

}  // namespace corridor
