#include "perception/roll_estimate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Angle between segment `s` and the direction from its middle to the homogeneous point `h`.
double AngleTo(const cv::Vec4d& s, const cv::Vec3d& h) {
  const double ax = s[0], ay = s[1], bx = s[2], by = s[3];
  const double length = std::hypot(bx - ax, by - ay);
  const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
  const double tx = h[0] - h[2] * mx, ty = h[1] - h[2] * my;
  const double norm = std::hypot(tx, ty);
  if (!(length > 0) || !(norm > 0)) return M_PI / 2;
  const double ux = (bx - ax) / length, uy = (by - ay) / length;
  return std::asin(std::min(1.0, std::abs(ux * ty - uy * tx) / norm));
}

// A near-vertical segment's line to a fraction of a pixel: on each of its rows, the peak of the
// horizontal gradient's magnitude within 2 px of it, placed by a parabola through three samples;
// then x = a + b y fitted to them by least squares, once more without the rows more than 1 px
// off. Hough's integer end points tilt a 50-pixel segment by up to a degree, as much as the
// rolls sought. Returns the segment unchanged when fewer than half its rows have a peak.
cv::Vec4d RefineVertical(const cv::Vec4i& s, const cv::Mat& gx) {
  const cv::Vec4d as_found(s[0], s[1], s[2], s[3]);
  const int y0 = std::max(1, std::min(s[1], s[3])), y1 = std::min(gx.rows - 2, std::max(s[1], s[3]));
  if (y1 - y0 < 4 || s[1] == s[3]) return as_found;
  const double slope = double(s[2] - s[0]) / (s[3] - s[1]);
  std::vector<cv::Point2d> peaks;
  for (int y = y0; y <= y1; ++y) {
    const int x = static_cast<int>(std::lround(s[0] + slope * (y - s[1])));
    int best = -1;
    float best_g = 0;
    for (int c = std::max(1, x - 2); c <= std::min(gx.cols - 2, x + 2); ++c) {
      const float g = std::abs(gx.at<float>(y, c));
      if (g > best_g) best_g = g, best = c;
    }
    if (best < 0) continue;
    const double l = std::abs(gx.at<float>(y, best - 1)), r = std::abs(gx.at<float>(y, best + 1));
    if (!(best_g >= l && best_g >= r)) continue;
    const double curvature = l - 2 * best_g + r;
    peaks.emplace_back(best + (curvature < 0 ? 0.5 * (l - r) / curvature : 0.0), y);
  }
  if (2 * peaks.size() < static_cast<size_t>(y1 - y0 + 1)) return as_found;
  double a = 0, b = 0;
  for (int pass = 0; pass < 2; ++pass) {
    double n = 0, sy = 0, sx = 0, syy = 0, sxy = 0;
    for (const cv::Point2d& p : peaks) {
      if (pass == 1 && std::abs(p.x - (a + b * p.y)) > 1.0) continue;
      n += 1, sy += p.y, sx += p.x, syy += p.y * p.y, sxy += p.x * p.y;
    }
    const double det = n * syy - sy * sy;
    if (n < 5 || !(det > 0)) return as_found;
    b = (n * sxy - sy * sx) / det;
    a = (sx - b * sy) / n;
  }
  return cv::Vec4d(a + b * s[1], s[1], a + b * s[3], s[3]);
}

}  // namespace

bool RollEstimateOptions::Check(std::string* why) const {
  std::string reason;
  if (!(max_roll_deg > 0 && max_roll_deg <= 30) || !(step_deg > 0 && step_deg <= max_roll_deg)) {
    reason = "roll: max_roll_deg must be in (0, 30] and step_deg in (0, max_roll_deg]";
  } else if (!(inlier_deg > 0) || !(candidate_deg >= inlier_deg) || !(corridor_deg >= 0)) {
    reason = "roll: inlier_deg must be > 0, candidate_deg >= inlier_deg, corridor_deg >= 0";
  } else if (!(min_length_px > 0) || min_segments < 1 || min_each_side < 0 ||
             !(max_cost_fraction > 0 && max_cost_fraction <= 1)) {
    reason =
        "roll: min_length_px must be > 0, min_segments >= 1, min_each_side >= 0, "
        "max_cost_fraction in (0, 1]";
  }
  if (why != nullptr) *why = reason;
  return reason.empty();
}

cv::Mat RollTurn(const Camera& camera, double roll) {
  // p' = K Rz(roll) K^-1 p with Rz(r) = [cos r, -sin r; sin r, cos r] on normalised coordinates.
  const double c = std::cos(roll), s = std::sin(roll);
  const double a = c, b = -s * camera.fx / camera.fy, d = s * camera.fy / camera.fx, e = c;
  return (cv::Mat_<double>(2, 3) << a, b, camera.cx - a * camera.cx - b * camera.cy, d, e,
          camera.cy - d * camera.cx - e * camera.cy);
}

RollEstimate EstimateRoll(const cv::Mat& bgr, const Camera& camera,
                          const CorridorGeometry& geometry, const RollEstimateOptions& options) {
  RollEstimate out;
  if (bgr.empty() || bgr.type() != CV_8UC3 || !(camera.fx > 0) || !(camera.fy > 0)) return out;
  cv::Mat grey, edges;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Canny(grey, edges, 40, 120);
  std::vector<cv::Vec4i> segments;
  cv::HoughLinesP(edges, segments, 1, CV_PI / 360, 30, options.min_length_px, 3);
  const double th = geometry.pitch, ph = geometry.yaw;
  // The vertical vanishing point of a camera rolled by r: K Rz(r) (0, cos th, sin th).
  const auto vertical_vp = [&](double r) {
    const double vx = -std::sin(r) * std::cos(th), vy = std::cos(r) * std::cos(th);
    const double vz = std::sin(th);
    return cv::Vec3d(camera.fx * vx + camera.cx * vz, camera.fy * vy + camera.cy * vz, vz);
  };
  // The corridor's vanishing point, K R e_z with R = Rx(th) Ry(ph): lines toward it run along
  // the corridor, however steep.
  const double dx = std::sin(ph), dy = -std::sin(th) * std::cos(ph), dz = std::cos(th) * std::cos(ph);
  const cv::Vec3d corridor_vp(camera.fx * dx + camera.cx * dz, camera.fy * dy + camera.cy * dz,
                              dz);
  const double corridor_u = std::abs(dz) > 1e-9 ? corridor_vp[0] / dz : camera.cx;
  // A pixel whose ray meets the floor between the walls (the frame's own fit) is floor: a
  // carpet's or a tile's edges there are not the walls' verticals, however steep.
  const auto on_floor = [&](double u, double v) {
    if (!(geometry.camera_height > 0) || !(geometry.width > 0)) return false;
    const double x = (u - camera.cx) / camera.fx, y = (v - camera.cy) / camera.fy;
    // The floor meets the ray at z = h / (n.r), whose lateral X = z (m.r) (geometry.md, 2-3).
    const double n_r = std::cos(th) * y + std::sin(th);
    const double m_r = std::cos(ph) * x + std::sin(th) * std::sin(ph) * y - std::cos(th) * std::sin(ph);
    if (!(n_r > 0)) return false;
    const double lateral = geometry.camera_height * m_r / n_r;
    return lateral > -geometry.LeftDistance() && lateral < geometry.RightDistance();
  };
  std::vector<cv::Vec4d> candidates;
  const cv::Vec3d level = vertical_vp(0);
  cv::Mat gx;
  for (const cv::Vec4i& found : segments) {
    const cv::Vec4d s(found[0], found[1], found[2], found[3]);
    if (AngleTo(s, level) > options.candidate_deg * kDeg) continue;
    if (AngleTo(s, corridor_vp) < options.corridor_deg * kDeg) continue;
    if (on_floor(s[0], s[1]) && on_floor(s[2], s[3])) continue;
    if (gx.empty()) cv::Sobel(grey, gx, CV_32F, 1, 0);
    candidates.push_back(RefineVertical(found, gx));
  }
  const double cap = options.inlier_deg * kDeg;
  double best_cost = 1e300, cost_level = 0, best_roll = 0;
  int best_inliers = 0, best_each_side = 0;
  const int steps = static_cast<int>(std::lround(options.max_roll_deg / options.step_deg));
  for (int i = -steps; i <= steps; ++i) {
    const double r = i * options.step_deg * kDeg;
    const cv::Vec3d vp = vertical_vp(r);
    double cost = 0;
    int inliers = 0, left = 0, right = 0;
    for (const cv::Vec4d& s : candidates) {
      const double angle = AngleTo(s, vp);
      const double length = std::hypot(s[2] - s[0], s[3] - s[1]);
      cost += length * std::min(angle * angle, cap * cap);
      if (angle < cap) {
        ++inliers;
        (0.5 * (s[0] + s[2]) < corridor_u ? left : right) += 1;
      }
    }
    if (i == 0) cost_level = cost;
    if (cost < best_cost) {
      best_cost = cost;
      best_roll = r;
      best_inliers = inliers;
      best_each_side = std::min(left, right);
    }
  }
  out.segments = best_inliers;
  // The vertical vanishing point fitted freely to the agreeing segments: the direction v (camera
  // frame, unit) nearest to every segment's plane through the camera centre, length-weighted.
  // Its own pitch follows the segments, so a pitch error of the corridor's fit (which tilts the
  // two walls' verticals apart, and mimics a roll where one wall has more of them) does not
  // become a roll. A camera rolled by r sees v = Rz(r) (0, cos th, sin th): r = atan2(-vx, vy).
  const cv::Vec3d best_vp = vertical_vp(best_roll);
  cv::Matx33d scatter = cv::Matx33d::zeros();
  for (const cv::Vec4d& s : candidates) {
    if (AngleTo(s, best_vp) >= cap) continue;
    const cv::Vec3d a((s[0] - camera.cx) / camera.fx, (s[1] - camera.cy) / camera.fy, 1.0);
    const cv::Vec3d b((s[2] - camera.cx) / camera.fx, (s[3] - camera.cy) / camera.fy, 1.0);
    cv::Vec3d plane = a.cross(b);
    const double n = cv::norm(plane);
    if (!(n > 0)) continue;
    plane /= n;
    scatter += std::hypot(s[2] - s[0], s[3] - s[1]) * (plane * plane.t());
  }
  cv::Mat values, vectors;
  cv::eigen(cv::Mat(scatter), values, vectors);
  cv::Vec3d v(vectors.at<double>(2, 0), vectors.at<double>(2, 1), vectors.at<double>(2, 2));
  if (v[1] < 0) v = -v;
  const double free_roll = std::atan2(-v[0], v[1]);
  out.found = best_inliers >= options.min_segments && best_each_side >= options.min_each_side &&
              cost_level > 0 && best_cost <= options.max_cost_fraction * cost_level &&
              std::abs(free_roll) >= options.step_deg * kDeg;
  out.roll = out.found ? free_roll : 0.0;
  return out;
}

}  // namespace corridor
