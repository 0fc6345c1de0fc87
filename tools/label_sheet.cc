#include "tools/label_sheet.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "corridor_depth/corridor_frame.h"

namespace corridor {

cv::Mat LabelTile(const cv::Mat& bgr, const JunctionLabel& label, bool ok,
                  const CorridorGeometry& geometry, double roll, const Camera& camera,
                  const std::string& caption, int tile_width) {
  cv::Mat photo = bgr.clone();
  const int thick = std::max(2, photo.rows / 150);
  for (int s = 0; s < 2; ++s) {
    if (!label.has_side[s]) continue;
    cv::line(photo, cv::Point2d(label.side[s][0].x(), label.side[s][0].y()),
             cv::Point2d(label.side[s][1].x(), label.side[s][1].y()), cv::Scalar(0, 220, 0),
             2 * thick, cv::LINE_AA);
  }
  if (ok) {
    for (int s = 0; s < 2; ++s) {
      // The floor junction from 0.2 m in front of the camera to far along the corridor, clipped.
      const double x = s == 0 ? -geometry.LeftDistance() : geometry.RightDistance();
      const CorridorRotation<double> r(geometry.pitch, geometry.yaw);
      std::vector<cv::Point> points;
      for (double z = 0.2; z < 2000; z *= 1.15) {
        const Vec3<double> c = TurnedByRoll(r.ToCamera({x, geometry.camera_height, z}), roll);
        if (!(c.z > 0.05)) continue;
        const Eigen::Vector2d p = camera.Distort(camera.Project({c.x, c.y, c.z}));
        if (p.allFinite() && std::abs(p.x()) < 1e5 && std::abs(p.y()) < 1e5) {
          points.emplace_back(cvRound(p.x()), cvRound(p.y()));
        }
      }
      for (size_t i = 1; i < points.size(); ++i) {
        cv::Point a = points[i - 1], b = points[i];
        if (cv::clipLine(photo.size(), a, b)) {
          cv::line(photo, a, b, cv::Scalar(0, 0, 255), thick, cv::LINE_AA);
        }
      }
    }
  }
  const double scale = static_cast<double>(tile_width) / photo.cols;
  cv::Mat small;
  cv::resize(photo, small, cv::Size(tile_width, std::max(1, cvRound(photo.rows * scale))), 0, 0,
             cv::INTER_AREA);
  cv::Mat tile(small.rows + 22, tile_width, CV_8UC3, cv::Scalar(255, 255, 255));
  small.copyTo(tile(cv::Rect(0, 0, small.cols, small.rows)));
  cv::putText(tile, caption, cv::Point(4, small.rows + 16), cv::FONT_HERSHEY_SIMPLEX, 0.42,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  return tile;
}

cv::Mat ContactSheet(const std::vector<cv::Mat>& tiles, int columns) {
  if (tiles.empty() || columns < 1) return cv::Mat();
  int width = 0, row_height = 0;
  for (const auto& t : tiles) width = std::max(width, t.cols), row_height = std::max(row_height, t.rows);
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  const int gap = 6;
  cv::Mat sheet((row_height + gap) * rows, (width + gap) * columns, CV_8UC3,
                cv::Scalar(255, 255, 255));
  for (size_t i = 0; i < tiles.size(); ++i) {
    const int r = static_cast<int>(i) / columns, c = static_cast<int>(i) % columns;
    tiles[i].copyTo(sheet(cv::Rect(c * (width + gap), r * (row_height + gap), tiles[i].cols,
                                   tiles[i].rows)));
  }
  return sheet;
}

}  // namespace corridor
