#include "pipeline/confidence_mask.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "corridor_depth/corridor_frame.h"
#include "perception/appearance.h"
#include "pipeline/box_surface.h"

namespace corridor {
namespace {

constexpr uchar kFloor = 1, kWall = 2;  // Surface labels; 0 = other (ceiling, baseboard, none).
constexpr double kBaseboardBand = 0.2;  // Wall points lower than this (m) are left to the floor test.

// The box model's nearest surface at each pixel.
cv::Mat SurfaceLabels(const Camera& camera, const CorridorGeometry& g) {
  const BoxFrame box(g);
  cv::Mat floor(camera.image_height, camera.image_width, CV_8U);
  for (int v = 0; v < camera.image_height; ++v) {
    uchar* row = floor.ptr<uchar>(v);
    for (int u = 0; u < camera.image_width; ++u) {
      const Vec3<double> ray = RayOfRawPixel(camera, u, v);
      const BoxHit hit = FirstBoxSurface(box, ray);
      if (hit.surface == BoxSurface::kFloor) {
        row[u] = kFloor;
      } else if (hit.surface == BoxSurface::kWall) {
        // Height of the wall point above the floor: h - Y_W, Y_W = z (n.r).
        row[u] = g.camera_height - hit.z * Dot(box.n, ray) > kBaseboardBand ? kWall : 0;
      } else {
        row[u] = 0;  // Ceiling, end wall (its own colour, not the side walls'), or nothing.
      }
    }
  }
  return floor;
}

}  // namespace

cv::Mat ComputeConfidenceMask(const cv::Mat& bgr, const cv::Mat& depth, const Camera& camera,
                              const CorridorGeometry& geometry, const ConfidenceOptions& options) {
  cv::Mat mask(bgr.size(), CV_8U, cv::Scalar(255));
  if (!depth.empty()) mask.setTo(0, ~(depth > 0));  // None: 0 or NaN.
  const cv::Mat labels = SurfaceLabels(camera, geometry);

  // Floor and walls: colour against the surface's median colour (the median filter removes grout
  // lines): objects and people on the floor, doors and furniture against the walls.
  cv::Mat smooth, lab;
  cv::medianBlur(bgr, smooth, 5);
  cv::cvtColor(smooth, lab, cv::COLOR_BGR2Lab);
  for (const uchar surface : {kFloor, kWall}) {
    std::vector<float> channel[3];
    for (int v = 0; v < lab.rows; v += 2) {
      for (int u = 0; u < lab.cols; u += 2) {
        if (labels.at<uchar>(v, u) != surface) continue;
        const cv::Vec3b p = lab.at<cv::Vec3b>(v, u);
        for (int c = 0; c < 3; ++c) channel[c].push_back(p[c]);
      }
    }
    if (channel[0].size() < 20) continue;
    cv::Vec3f reference;
    for (int c = 0; c < 3; ++c) {
      auto mid = channel[c].begin() + channel[c].size() / 2;
      std::nth_element(channel[c].begin(), mid, channel[c].end());
      reference[c] = *mid;
    }
    std::vector<float> distances;
    for (int v = 0; v < lab.rows; v += 2) {
      for (int u = 0; u < lab.cols; u += 2) {
        if (labels.at<uchar>(v, u) == surface) {
          distances.push_back(LabDistance(lab.at<cv::Vec3b>(v, u), reference));
        }
      }
    }
    // The spread from the lower quartile: objects may cover half of a wall in view.
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 4, distances.end());
    const float threshold = std::max(static_cast<float>(options.min_floor_distance),
                                     static_cast<float>(options.floor_color_sigmas) * 2.2f *
                                         distances[distances.size() / 4]);
    cv::Mat odd(bgr.size(), CV_8U, cv::Scalar(0));
    for (int v = 0; v < lab.rows; ++v) {
      for (int u = 0; u < lab.cols; ++u) {
        if (labels.at<uchar>(v, u) == surface &&
            LabDistance(lab.at<cv::Vec3b>(v, u), reference) > threshold) {
          odd.at<uchar>(v, u) = 255;
        }
      }
    }
    cv::morphologyEx(odd, odd, cv::MORPH_OPEN, cv::Mat::ones(3, 3, CV_8U));
    mask.setTo(0, odd);
  }

  // Walls: near-vertical edges are doors, frames, pillars and furniture.
  cv::Mat gray, edges;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  cv::GaussianBlur(gray, gray, cv::Size(0, 0), 1.0);
  cv::Canny(gray, edges, 30, 90, 3, true);
  std::vector<cv::Vec4i> segments;
  cv::HoughLinesP(edges, segments, 1, CV_PI / 180, 20, bgr.rows / 12.0, 4);
  cv::Mat vertical(bgr.size(), CV_8U, cv::Scalar(0));
  const double tolerance = std::tan(options.vertical_edge_deg * M_PI / 180.0);
  for (const auto& s : segments) {
    const double du = s[2] - s[0], dv = s[3] - s[1];
    if (std::abs(du) > tolerance * std::abs(dv)) continue;
    const cv::Point mid((s[0] + s[2]) / 2, (s[1] + s[3]) / 2);
    if (labels.at<uchar>(mid.y, mid.x) == kFloor) continue;  // Only edges on the walls.
    cv::line(vertical, {s[0], s[1]}, {s[2], s[3]}, cv::Scalar(255), 2 * options.edge_margin_px + 1);
  }
  mask.setTo(0, vertical);
  return mask;
}

}  // namespace corridor
