#include "perception/roll_estimate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Angle between segment `s` and the direction from its middle to the homogeneous point `h`.
double AngleTo(const cv::Vec4i& s, const cv::Vec3d& h) {
  const double ax = s[0], ay = s[1], bx = s[2], by = s[3];
  const double length = std::hypot(bx - ax, by - ay);
  const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
  const double tx = h[0] - h[2] * mx, ty = h[1] - h[2] * my;
  const double norm = std::hypot(tx, ty);
  if (!(length > 0) || !(norm > 0)) return M_PI / 2;
  const double ux = (bx - ax) / length, uy = (by - ay) / length;
  return std::asin(std::min(1.0, std::abs(ux * ty - uy * tx) / norm));
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
  std::vector<cv::Vec4i> candidates;
  const cv::Vec3d level = vertical_vp(0);
  for (const cv::Vec4i& s : segments) {
    if (AngleTo(s, level) > options.candidate_deg * kDeg) continue;
    if (AngleTo(s, corridor_vp) < options.corridor_deg * kDeg) continue;
    candidates.push_back(s);
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
    for (const cv::Vec4i& s : candidates) {
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
  out.found = best_inliers >= options.min_segments && best_each_side >= options.min_each_side &&
              cost_level > 0 && best_cost <= options.max_cost_fraction * cost_level &&
              best_roll != 0;
  out.roll = out.found ? best_roll : 0.0;
  return out;
}

}  // namespace corridor
