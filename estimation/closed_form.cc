#include "estimation/closed_form.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/symmetric_eigen.h"
#include "corridor_depth/corridor_frame.h"
#include "corridor_depth/line_inliers.h"
#include "corridor_depth/virtual_camera.h"

namespace corridor {
namespace {

// Median lateral position X_W of the points' floor intersections (weighted: the position where
// half the weight lies on either side; `weights` empty = all 1), or false if any misses the floor.
bool MedianLateralPosition(const FloorIntrinsics& k, const CorridorRotation<double>& rotation,
                           const std::vector<Eigen::Vector2d>& points,
                           const std::vector<double>& weights, double* median_x) {
  // The thread's, reused from call to call.
  thread_local std::vector<double> thread_x;
  thread_local std::vector<std::pair<double, double>> thread_weighted;
  std::vector<double>& x = thread_x;
  x.clear();
  for (const auto& p : points) {
    Vec3<double> floor_point;
    if (!BackProjectToFloor(k, rotation, p.x(), p.y(), &floor_point)) return false;
    x.push_back(floor_point.x);
  }
  if (weights.empty()) {
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    *median_x = x[x.size() / 2];
    return true;
  }
  std::vector<std::pair<double, double>>& weighted = thread_weighted;
  weighted.clear();
  double total = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    weighted.emplace_back(x[i], weights[i]);
    total += weights[i];
  }
  std::sort(weighted.begin(), weighted.end());
  double below = 0;
  *median_x = weighted.back().first;
  for (const auto& [value, weight] : weighted) {
    below += weight;
    if (below > 0.5 * total) {
      *median_x = value;
      break;
    }
  }
  return true;
}

// The points that lie on their side's dominant line (LineInlierMask), so that gross outliers
// neither tilt the fitted line nor shift the lateral positions, with their weights (none when
// `weights` is empty). Into *inliers and *inlier_weights, which keep their memory.
void Inliers(const std::vector<Eigen::Vector2d>& points, const std::vector<double>& weights,
             std::vector<Eigen::Vector2d>* inliers, std::vector<double>* inlier_weights) {
  thread_local std::vector<char> thread_keep;
  std::vector<char>& keep = thread_keep;
  LineInlierMask(points, &keep);
  inliers->clear();
  inlier_weights->clear();
  for (size_t i = 0; i < points.size(); ++i) {
    if (!keep[i]) continue;
    inliers->push_back(points[i]);
    if (!weights.empty()) inlier_weights->push_back(weights[i]);
  }
}

}  // namespace

bool FitImageLine(const std::vector<Eigen::Vector2d>& points, Eigen::Vector3d* line) {
  return FitImageLine(points, {}, line);
}

bool FitImageLine(const std::vector<Eigen::Vector2d>& points, const std::vector<double>& weights,
                  Eigen::Vector3d* line) {
  if (points.size() < 2 || !(weights.empty() || weights.size() == points.size())) return false;
  const auto weight = [&](size_t i) { return weights.empty() ? 1.0 : weights[i]; };
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  double total = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    mean += weight(i) * points[i];
    total += weight(i);
  }
  if (!(total > 0)) return false;
  mean /= total;
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (size_t i = 0; i < points.size(); ++i) {
    scatter += weight(i) * (points[i] - mean) * (points[i] - mean).transpose();
  }
  if (scatter.trace() <= 1e-12) return false;
  const Eigen::Vector2d normal = SmallestEigenvector(scatter);
  *line = Eigen::Vector3d(normal.x(), normal.y(), -normal.dot(mean));
  return true;
}

Status SolveClosedForm(const CorridorObservation& observation, CorridorGeometry* geometry) {
  std::string why;
  if (!observation.Check(&why)) return Status::InvalidArgument(why);
  // The thread's, reused from call to call.
  thread_local std::vector<Eigen::Vector2d> thread_left, thread_right;
  thread_local std::vector<double> thread_left_weights, thread_right_weights;
  std::vector<Eigen::Vector2d>& left = thread_left;
  std::vector<Eigen::Vector2d>& right = thread_right;
  std::vector<double>& left_weights = thread_left_weights;
  std::vector<double>& right_weights = thread_right_weights;
  Inliers(observation.left, observation.left_weights, &left, &left_weights);
  Inliers(observation.right, observation.right_weights, &right, &right_weights);
  Eigen::Vector3d left_line, right_line;
  if (!FitImageLine(left, left_weights, &left_line) ||
      !FitImageLine(right, right_weights, &right_line)) {
    return Status::ImplausibleGeometry("a junction's points are all the same point");
  }
  const Eigen::Vector3d vp = left_line.cross(right_line);
  // Parallel image lines: the vanishing point is at infinity (|w| tiny against |u|, |v|).
  if (std::abs(vp.z()) < 1e-9 * vp.head<2>().norm()) {
    return Status::ImplausibleGeometry("junction lines are parallel: vanishing point at infinity");
  }
  Eigen::Matrix3d k_inv = Eigen::Matrix3d::Identity();
  k_inv(0, 0) = 1.0 / observation.fx;
  k_inv(1, 1) = 1.0 / observation.fy;
  k_inv(0, 2) = -observation.cx / observation.fx;
  k_inv(1, 2) = -observation.cy / observation.fy;
  Eigen::Vector3d d = (k_inv * vp).normalized();
  if (d.z() < 0) d = -d;
  if (d.z() < 1e-3) {
    return Status::ImplausibleGeometry("vanishing point lies 90 degrees off the optical axis");
  }
  const double yaw = std::asin(std::clamp(d.x(), -1.0, 1.0));
  const double pitch = std::atan2(-d.y(), d.z());

  const FloorIntrinsics k{observation.fx, observation.fy, observation.cx, observation.cy,
                          observation.camera_height};
  const CorridorRotation<double> rotation(pitch, yaw);
  double left_x = 0, right_x = 0;
  if (!MedianLateralPosition(k, rotation, left, left_weights, &left_x) ||
      !MedianLateralPosition(k, rotation, right, right_weights, &right_x)) {
    return Status::ImplausibleGeometry(
        "junction points lie above the horizon of the vanishing point (not on the floor)");
  }
  const double d_left = -left_x, d_right = right_x;
  if (!(d_left > 0 && d_right > 0)) {
    return Status::ImplausibleGeometry("the camera is not between the two junctions");
  }
  geometry->yaw = yaw;
  geometry->pitch = pitch;
  geometry->SetWallDistances(d_left, d_right);
  geometry->camera_height = observation.camera_height;
  return Status::Ok();
}

}  // namespace corridor
