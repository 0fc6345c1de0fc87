#include "corridor_depth/visualization.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "corridor_depth/corridor_frame.h"

namespace corridor {
namespace {

const cv::Scalar kLeftColor(60, 220, 60);    // BGR green
const cv::Scalar kRightColor(220, 60, 220);  // BGR magenta
const cv::Scalar kSegmentColor(160, 160, 160);

cv::Point ToPoint(const Eigen::Vector2d& p) {
  return {cvRound(p.x()), cvRound(p.y())};
}

void DrawLine(cv::Mat* canvas, const JunctionLine& line, const Eigen::Vector2d& vp, bool has_vp,
              const cv::Scalar& color) {
  for (const auto& p : line.support) cv::circle(*canvas, ToPoint(p), 1, color * 0.6, cv::FILLED);
  const Eigen::Vector2d far = has_vp ? vp : line.far_end;
  cv::line(*canvas, ToPoint(line.near_end), ToPoint(far), color, 2, cv::LINE_AA);
}

// The floor/wall junctions (X_W = -d_l and d_r, Y_W = h) of the geometry, from 0.5 m to 60 m
// along the corridor, as thin white polylines; in the frame's camera, turned by the roll it was
// recovered level from.
void DrawGeometryJunctions(cv::Mat* canvas, const CorridorGeometry& g, double roll,
                           const Camera& camera) {
  if (!camera.CheckIntrinsics(nullptr) || camera.image_width != canvas->cols ||
      camera.image_height != canvas->rows) {
    return;
  }
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const bool distorted = camera.HasDistortion();
  for (const double x : {-g.LeftDistance(), g.RightDistance()}) {
    std::vector<cv::Point> points;
    for (int i = 0; i <= 60; ++i) {
      const double z = 1.0 / (2.0 + (1.0 / 60 - 2.0) * i / 60.0);  // Uniform in 1/Z.
      const Vec3<double> c = TurnedByRoll(r.ToCamera({x, g.camera_height, z}), roll);
      if (c.z < 0.05) continue;
      Eigen::Vector2d p = camera.Project({c.x, c.y, c.z});
      if (distorted) p = camera.Distort(p);
      if (!p.allFinite() || std::abs(p.x()) > 1e5 || std::abs(p.y()) > 1e5) continue;
      points.push_back(ToPoint(p));
    }
    if (points.size() >= 2) {
      cv::polylines(*canvas, points, false, cv::Scalar(255, 255, 255), 1, cv::LINE_8);
    }
  }
}

void PutCaption(cv::Mat* image, const std::string& text, int row) {
  const cv::Point origin(6, 16 + 16 * row);
  cv::putText(*image, text, origin, cv::FONT_HERSHEY_SIMPLEX, 0.42, cv::Scalar(0, 0, 0), 3,
              cv::LINE_AA);
  cv::putText(*image, text, origin, cv::FONT_HERSHEY_SIMPLEX, 0.42, cv::Scalar(255, 255, 255), 1,
              cv::LINE_AA);
}

// The text cut (with "...") to what PutCaption fits in `width` pixels.
std::string FitCaption(const std::string& text, int width) {
  const auto fits = [&](const std::string& t) {
    int baseline = 0;
    return cv::getTextSize(t, cv::FONT_HERSHEY_SIMPLEX, 0.42, 3, &baseline).width <= width - 12;
  };
  if (fits(text)) return text;
  for (size_t n = text.size(); n > 0; --n) {
    const std::string cut = text.substr(0, n - 1) + "...";
    if (fits(cut)) return cut;
  }
  return "";
}

std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2fm", value);
  return text;
}

}  // namespace

cv::Mat ColorizeDepth(const cv::Mat& depth, double max_depth) {
  cv::Mat scaled;
  depth.convertTo(scaled, CV_8U, 255.0 / max_depth);
  cv::Mat color;
  cv::applyColorMap(scaled, color, cv::COLORMAP_TURBO);
  color.setTo(cv::Scalar(0, 0, 0), ~(depth > 0));  // None: 0 or NaN.
  return color;
}

cv::Mat DepthColorBar(int height, double max_depth) {
  const int bar_width = 16, label_width = 44;
  cv::Mat ramp(height, 1, CV_32F);
  for (int v = 0; v < height; ++v) {
    ramp.at<float>(v, 0) = static_cast<float>(max_depth * (height - 1 - v) / (height - 1.0));
  }
  cv::Mat bar = cv::Mat::zeros(height, bar_width + label_width, CV_8UC3);
  cv::Mat colors = ColorizeDepth(ramp, max_depth);
  cv::resize(colors, bar(cv::Rect(0, 0, bar_width, height)), cv::Size(bar_width, height), 0, 0,
             cv::INTER_NEAREST);
  for (int i = 0; i <= 4; ++i) {
    const double value = max_depth * i / 4.0;
    const int v = cvRound((height - 1) * (1.0 - i / 4.0));
    char label[32];
    std::snprintf(label, sizeof(label), "%.0fm", value);
    cv::putText(bar, label, cv::Point(bar_width + 3, std::clamp(v + 4, 10, height - 2)),
                cv::FONT_HERSHEY_SIMPLEX, 0.38, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  }
  return bar;
}

cv::Mat DrawJunctions(const cv::Mat& bgr, const JunctionPair& junctions) {
  cv::Mat canvas = bgr.clone();
  for (const auto& s : junctions.segments) {
    cv::line(canvas, cv::Point(cvRound(s[0]), cvRound(s[1])), cv::Point(cvRound(s[2]), cvRound(s[3])),
             kSegmentColor, 1, cv::LINE_AA);
  }
  if (!junctions.status.ok()) {
    // One junction only: draw it (towards its vanishing point when other lines gave one).
    if (junctions.has_single) {
      DrawLine(&canvas, junctions.single, junctions.single_vp, junctions.single_has_vp,
               junctions.single_is_left ? kLeftColor : kRightColor);
      if (junctions.single_has_vp) {
        cv::drawMarker(canvas, ToPoint(junctions.single_vp), cv::Scalar(0, 255, 255),
                       cv::MARKER_CROSS, 12, 2);
      }
    }
    return canvas;
  }
  DrawLine(&canvas, junctions.left, junctions.vanishing_point, true, kLeftColor);
  DrawLine(&canvas, junctions.right, junctions.vanishing_point, true, kRightColor);
  cv::drawMarker(canvas, ToPoint(junctions.vanishing_point), cv::Scalar(0, 255, 255),
                 cv::MARKER_CROSS, 12, 2);
  return canvas;
}

cv::Mat HorizontalConcat(const std::vector<cv::Mat>& images, int gap) {
  int height = 0;
  for (const auto& image : images) height = std::max(height, image.rows);
  std::vector<cv::Mat> parts;
  for (size_t i = 0; i < images.size(); ++i) {
    cv::Mat part = images[i];
    if (part.channels() == 1) cv::cvtColor(part, part, cv::COLOR_GRAY2BGR);
    if (part.rows != height) {
      cv::Mat padded = cv::Mat::zeros(height, part.cols, CV_8UC3);
      part.copyTo(padded(cv::Rect(0, 0, part.cols, part.rows)));
      part = padded;
    }
    parts.push_back(part);
    if (i + 1 < images.size() && gap > 0) parts.push_back(cv::Mat::zeros(height, gap, CV_8UC3));
  }
  cv::Mat out;
  cv::hconcat(parts, out);
  return out;
}

cv::Mat MakeResultPanel(const cv::Mat& bgr, const RecoverDepthResult& result, double max_depth) {
  cv::Mat lines = DrawJunctions(bgr, result.junctions);
  cv::Mat depth_color = result.depth.empty() ? cv::Mat::zeros(bgr.size(), CV_8UC3)
                                             : ColorizeDepth(result.depth, max_depth);
  char text[160];
  if (result.status.ok()) {
    std::snprintf(text, sizeof(text), "w=%.2fm off=%.2fm yaw=%.1fdeg pitch=%.1fdeg",
                  result.geometry.width, result.geometry.offset, result.geometry.yaw * 180 / M_PI,
                  result.geometry.pitch * 180 / M_PI);
    PutCaption(&lines, text, 0);
    const CorridorGeometry& g = result.geometry;
    std::string extent;
    if (g.HasCeiling()) extent += "ceiling " + Metres(g.ceiling_height) + "  ";
    if (g.HasEndWall()) extent += "end wall at " + Metres(g.end_distance);
    if (!extent.empty()) PutCaption(&lines, extent, 1);
    if (!result.fallback.empty()) {
      DrawGeometryJunctions(&lines, g, result.roll, result.camera);
      PutCaption(&lines, FitCaption(result.fallback, lines.cols), extent.empty() ? 1 : 2);
    }
    std::snprintf(text, sizeof(text), "%.2f ms", result.times.total * 1e3);
    PutCaption(&depth_color, text, 0);
  } else {
    PutCaption(&lines, result.status.ToString().substr(0, 70), 0);
  }
  return HorizontalConcat({lines, depth_color, DepthColorBar(bgr.rows, max_depth)});
}

}  // namespace corridor
