#include "perception/ceiling_detector.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/corridor_frame.h"

namespace corridor {
namespace {

// Raw pixel of a corridor-frame point, or false when it is behind the camera or off the image.
bool ProjectToImage(const Camera& camera, const CorridorRotation<double>& r, double x, double y,
                    double z, cv::Point* pixel) {
  const Vec3<double> c = r.ToCamera({x, y, z});
  if (c.z < 0.05) return false;
  const Eigen::Vector2d raw = camera.Distort(camera.Project({c.x, c.y, c.z}));
  if (!raw.allFinite()) return false;
  pixel->x = cvRound(raw.x());
  pixel->y = cvRound(raw.y());
  return pixel->x >= 1 && pixel->y >= 1 && pixel->x < camera.image_width - 1 &&
         pixel->y < camera.image_height - 1;
}

// Fraction of the line's visible samples that have an edge pixel within 1 px.
double LineSupport(const cv::Mat& edges, const Camera& camera, const CorridorRotation<double>& r,
                   double wall_x, double y, const CeilingDetectorOptions& o) {
  int visible = 0, hits = 0;
  for (int i = 0; i < o.samples; ++i) {
    const double inv = 1.0 / o.near_distance +
                       (1.0 / o.far_distance - 1.0 / o.near_distance) * i / (o.samples - 1.0);
    cv::Point p;
    if (!ProjectToImage(camera, r, wall_x, y, 1.0 / inv, &p)) continue;
    ++visible;
    bool hit = false;
    for (int dv = -1; dv <= 1 && !hit; ++dv) {
      for (int du = -1; du <= 1 && !hit; ++du) hit = edges.at<uchar>(p.y + dv, p.x + du) != 0;
    }
    hits += hit;
  }
  return visible >= 8 ? static_cast<double>(hits) / visible : 0.0;
}

}  // namespace

bool CeilingDetectorOptions::Check(std::string* why) const {
  std::string reason;
  if (!(min_height > 0 && max_height > min_height && step > 0)) {
    reason = "ceiling search needs 0 < min_height < max_height and step > 0";
  } else if (!(near_distance > 0 && far_distance > near_distance) || samples < 10) {
    reason = "ceiling samples need 0 < near_distance < far_distance and >= 10 samples";
  } else if (!(min_support > 0 && min_support <= 1)) {
    reason = "min_support must be in (0, 1]";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

Status DetectCeiling(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g,
                     const CeilingDetectorOptions& o, CeilingEstimate* estimate) {
  *estimate = CeilingEstimate();
  std::string why;
  if (!o.Check(&why)) return Status::InvalidArgument("ceiling detector: " + why);
  if (bgr.empty() || bgr.cols != camera.image_width || bgr.rows != camera.image_height) {
    return Status::InvalidArgument("ceiling detector: image does not match the camera");
  }
  cv::Mat gray, edges;
  if (bgr.channels() == 1) {
    gray = bgr.clone();
  } else {
    cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  }
  cv::GaussianBlur(gray, gray, cv::Size(0, 0), 1.0);
  cv::Canny(gray, edges, 20, 60, 3, true);

  const CorridorRotation<double> r(g.pitch, g.yaw);
  const double h = g.camera_height, x_left = -g.LeftDistance(), x_right = g.RightDistance();
  double best_score = 0, best_height = 0, best_left = 0, best_right = 0;
  const double lo = std::max(o.min_height, h + 0.1);
  for (double height = lo; height <= o.max_height; height += o.step) {
    const double y = h - height;  // Corridor Y of the ceiling (negative: above the camera).
    const double left = LineSupport(edges, camera, r, x_left, y, o);
    const double right = LineSupport(edges, camera, r, x_right, y, o);
    const double score = left + right;
    if (score > best_score) {
      best_score = score;
      best_height = height;
      best_left = left;
      best_right = right;
    }
  }
  estimate->left_support = best_left;
  estimate->right_support = best_right;
  if (std::max(best_left, best_right) < o.min_support) {
    estimate->reason = "no ceiling/wall junction follows the image's edges";
    return Status::Ok();
  }
  // Refine: every edge pixel within 2 px of an accepted line gives H_c from its ray and wall.
  std::vector<double> heights;
  const Vec3<double> n = r.FloorNormal(), m = r.WallNormal();
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 ? best_left : best_right) < o.min_support) continue;
    const double wall_x = side == 0 ? x_left : x_right;
    for (int i = 0; i < o.samples; ++i) {
      const double inv = 1.0 / o.near_distance +
                         (1.0 / o.far_distance - 1.0 / o.near_distance) * i / (o.samples - 1.0);
      cv::Point p;
      if (!ProjectToImage(camera, r, wall_x, h - best_height, 1.0 / inv, &p)) continue;
      for (int dv = -2; dv <= 2; ++dv) {
        const int v = p.y + dv;
        if (v < 0 || v >= edges.rows || edges.at<uchar>(v, p.x) == 0) continue;
        const Eigen::Vector2d ideal = camera.Undistort({static_cast<double>(p.x), static_cast<double>(v)});
        const Vec3<double> ray{(ideal.x() - camera.cx) / camera.fx,
                               (ideal.y() - camera.cy) / camera.fy, 1.0};
        const double mr = Dot(m, ray);
        if (std::abs(mr) < 1e-9) continue;
        const double z = wall_x / mr;  // The ray meets its wall plane X = wall_x at depth z.
        if (z <= 0) continue;
        heights.push_back(h - z * Dot(n, ray));  // H_c = h - Y_W.
      }
    }
  }
  if (heights.size() < 5) {
    estimate->reason = "too few edge pixels on the ceiling/wall junctions";
    return Status::Ok();
  }
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
  estimate->height = heights[heights.size() / 2];
  estimate->points = static_cast<int>(heights.size());
  estimate->found = estimate->height > h;
  if (!estimate->found) estimate->reason = "the ceiling estimate lies below the camera";
  return Status::Ok();
}

}  // namespace corridor
