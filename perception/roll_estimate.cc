#include "perception/roll_estimate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "perception/vertical_segments.h"

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
  } else if (!(min_spread >= 0 && min_spread <= 1) ||
             !(min_roll_deg >= 0 && min_roll_deg < max_roll_deg)) {
    reason = "roll: min_spread must be in [0, 1] and min_roll_deg in [0, max_roll_deg)";
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
  // Each row's floor span, which the segment search skips (less 3 px each side, for the walls'
  // verticals that end on the junction): where X = -d_l and X = d_r on the floor.
  // Per-thread buffers: they only grow, so a stream of frames allocates nothing here.
  thread_local std::vector<cv::Vec2i> floor_span;
  thread_local std::vector<cv::Vec4d> segments, candidates;
  floor_span.clear();
  if (geometry.camera_height > 0 && geometry.width > 0 && std::cos(ph) > 0) {
    floor_span.assign(bgr.rows, cv::Vec2i(0, 0));
    for (int v = 0; v < bgr.rows; ++v) {
      const double y = (v - camera.cy) / camera.fy;
      const double n_r = std::cos(th) * y + std::sin(th);
      if (!(n_r > 0)) continue;
      const auto column = [&](double lateral) {
        const double m_r = lateral * n_r / geometry.camera_height;
        const double x = (m_r - std::sin(th) * std::sin(ph) * y + std::cos(th) * std::sin(ph)) /
                         std::cos(ph);
        return camera.cx + camera.fx * x;
      };
      const double begin = std::max(0.0, column(-geometry.LeftDistance()) + 3);
      const double end = std::min<double>(bgr.cols, column(geometry.RightDistance()) - 3);
      if (end > begin) floor_span[v] = cv::Vec2i(static_cast<int>(std::ceil(begin)),
                                                 static_cast<int>(std::floor(end)));
    }
  }
  VerticalSegmentOptions find;
  find.min_length_px = options.min_length_px;
  FindVerticalSegments(bgr, find, floor_span, &segments);
  candidates.clear();
  const cv::Vec3d level = vertical_vp(0);
  for (const cv::Vec4d& s : segments) {
    if (AngleTo(s, level) > options.candidate_deg * kDeg) continue;
    if (AngleTo(s, corridor_vp) < options.corridor_deg * kDeg) continue;
    if (on_floor(s[0], s[1]) && on_floor(s[2], s[3])) continue;
    candidates.push_back(s);
  }
  const double cap = options.inlier_deg * kDeg;
  // Each candidate's middle, direction, length and side, for the search's many rolls.
  struct Candidate {
    double mx, my, ux, uy, length;
    bool left;
  };
  thread_local std::vector<Candidate> prepared;
  prepared.clear();
  for (const cv::Vec4d& s : candidates) {
    const double length = std::hypot(s[2] - s[0], s[3] - s[1]);
    if (!(length > 0)) continue;
    prepared.push_back({0.5 * (s[0] + s[2]), 0.5 * (s[1] + s[3]), (s[2] - s[0]) / length,
                        (s[3] - s[1]) / length, length, 0.5 * (s[0] + s[2]) < corridor_u});
  }
  struct Score {
    double cost = 0;
    int inliers = 0, each_side = 0;
  };
  const auto score = [&](double r) {
    const cv::Vec3d vp = vertical_vp(r);
    Score result;
    int left = 0, right = 0;
    for (const Candidate& c : prepared) {
      const double tx = vp[0] - vp[2] * c.mx, ty = vp[1] - vp[2] * c.my;
      const double norm = std::hypot(tx, ty);
      const double angle =
          norm > 0 ? std::asin(std::min(1.0, std::abs(c.ux * ty - c.uy * tx) / norm)) : M_PI / 2;
      result.cost += c.length * std::min(angle * angle, cap * cap);
      if (angle < cap) {
        ++result.inliers;
        (c.left ? left : right) += 1;
      }
    }
    result.each_side = std::min(left, right);
    return result;
  };
  // Coarse to fine: every fourth step over the whole range, then every step around the best.
  const double step = options.step_deg * kDeg;
  const int steps = static_cast<int>(std::lround(options.max_roll_deg / options.step_deg));
  const double cost_level = score(0).cost;
  Score best = score(0);
  double best_roll = 0;
  const auto consider = [&](int i) {
    const Score here = score(i * step);
    if (here.cost < best.cost) best = here, best_roll = i * step;
  };
  for (int i = -steps; i <= steps; i += 4) consider(i);
  const int coarse = static_cast<int>(std::lround(best_roll / step));
  for (int i = std::max(-steps, coarse - 3); i <= std::min(steps, coarse + 3); ++i) consider(i);
  const double best_cost = best.cost;
  const int best_inliers = best.inliers, best_each_side = best.each_side;
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
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = scatter(r, c);
  }
  // Eigenvalues in increasing order: the first column is the direction sought.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
  const Eigen::Vector3d smallest = solver.eigenvectors().col(0);
  cv::Vec3d v(smallest.x(), smallest.y(), smallest.z());
  if (v[1] < 0) v = -v;
  const double free_roll = std::atan2(-v[0], v[1]);
  const Eigen::Vector3d eigenvalues = solver.eigenvalues();
  const bool spread = eigenvalues(2) > 0 && eigenvalues(1) >= options.min_spread * eigenvalues(2);
  out.found = best_inliers >= options.min_segments &&
              (best_each_side >= options.min_each_side || spread) && cost_level > 0 &&
              best_cost <= options.max_cost_fraction * cost_level &&
              std::abs(free_roll) >= std::max(options.min_roll_deg, options.step_deg) * kDeg;
  out.roll = out.found ? free_roll : 0.0;
  return out;
}

}  // namespace corridor
