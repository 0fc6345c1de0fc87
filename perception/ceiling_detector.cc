#include "perception/ceiling_detector.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/corridor_frame.h"
#include "perception/corridor_projection.h"
#include "perception/oriented_edges.h"

namespace corridor {
namespace {

// The pixels of every searched line: for each height, the left then the right ceiling/wall
// junction, each as `samples` points evenly spaced in inverse distance along the corridor.
struct SearchLines {
  std::vector<double> heights;  // The searched ceiling heights, m.
  int samples = 0;              // Points per line.
  std::vector<cv::Point> pixels;  // [(height * 2 + side) * samples + i]; x = -1 where not visible.
  int top = 0, bottom = -1;     // Rows spanned by the visible pixels (bottom < top: none).

  const cv::Point* Line(size_t height, int side) const {
    return pixels.data() + (2 * height + side) * samples;
  }
};

void ProjectSearchLines(const Camera& camera, const CorridorGeometry& g,
                        const CeilingDetectorOptions& o, SearchLines* lines) {
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const double h = g.camera_height;
  const double wall_x[2] = {-g.LeftDistance(), g.RightDistance()};
  const double lo = std::max(o.min_height, h + 0.1);
  for (double height = lo; height <= o.max_height; height += o.step) {
    lines->heights.push_back(height);
  }
  lines->samples = o.samples;
  std::vector<double> depths(o.samples);
  for (int i = 0; i < o.samples; ++i) {
    const double inv = 1.0 / o.near_distance +
                       (1.0 / o.far_distance - 1.0 / o.near_distance) * i / (o.samples - 1.0);
    depths[i] = 1.0 / inv;
  }
  lines->pixels.assign(lines->heights.size() * 2 * o.samples, cv::Point(-1, -1));
  lines->top = camera.image_height;
  lines->bottom = -1;
  const bool distorted = camera.HasDistortion();
  cv::Point* out = lines->pixels.data();
  for (const double height : lines->heights) {
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < o.samples; ++i, ++out) {
        cv::Point p;
        const double y = h - height;  // Corridor Y of the ceiling (negative: above the camera).
        if (!ProjectCorridorPoint(camera, distorted, r, wall_x[side], y, depths[i], 1, &p)) continue;
        *out = p;
        lines->top = std::min(lines->top, p.y);
        lines->bottom = std::max(lines->bottom, p.y);
      }
    }
  }
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
  // Every candidate line is projected once; edges are computed only on the rows they cross.
  SearchLines lines;
  ProjectSearchLines(camera, g, o, &lines);
  if (lines.bottom < lines.top) {
    estimate->reason = "no ceiling/wall junction follows the image's edges";
    return Status::Ok();
  }
  const OrientedEdges edges = ComputeOrientedEdges(bgr, lines.top - 2, lines.bottom + 3);
  const int band_top = edges.top, band_bottom = edges.top + edges.edges.rows;

  double best_score = 0, best_left = 0, best_right = 0;
  size_t best = 0;
  for (size_t k = 0; k < lines.heights.size(); ++k) {
    const double left = OrientedLineSupport(lines.Line(k, 0), lines.samples, edges);
    const double right = OrientedLineSupport(lines.Line(k, 1), lines.samples, edges);
    const double support[2] = {left, right};
    for (int side = 0; side < 2; ++side) {
      if (support[side] > estimate->side_support[side]) {
        estimate->side_support[side] = support[side];
        estimate->side_height[side] = lines.heights[k];
      }
    }
    const double score = left + right;
    if (score > best_score) {
      best_score = score;
      best = k;
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
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const double h = g.camera_height;
  std::vector<double> heights;
  const Vec3<double> n = r.FloorNormal(), m = r.WallNormal();
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 ? best_left : best_right) < o.min_support) continue;
    const double wall_x = side == 0 ? -g.LeftDistance() : g.RightDistance();
    const cv::Point* line = lines.Line(best, side);
    for (int i = 0; i < lines.samples; ++i) {
      const cv::Point p = line[i];
      if (p.x < 0) continue;
      for (int dv = -2; dv <= 2; ++dv) {
        const int v = p.y + dv;
        if (v < band_top || v >= band_bottom) continue;
        if (edges.edges.at<uchar>(v - band_top, p.x) == 0) continue;
        const Vec3<double> ray = RayOfRawPixel(camera, p.x, v);
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
