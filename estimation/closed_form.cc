#include "estimation/closed_form.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "core/corridor_frame.h"
#include "estimation/virtual_camera.h"

namespace corridor {
namespace {

// Mean lateral position X_W of the points' floor intersections, or false if any misses the floor.
bool MeanLateralPosition(const FloorIntrinsics& k, const CorridorRotation<double>& rotation,
                         const std::vector<Eigen::Vector2d>& points, double* mean_x) {
  double sum = 0;
  for (const auto& p : points) {
    Vec3<double> floor_point;
    if (!BackProjectToFloor(k, rotation, p.x(), p.y(), &floor_point)) return false;
    sum += floor_point.x;
  }
  *mean_x = sum / static_cast<double>(points.size());
  return true;
}

}  // namespace

bool FitImageLine(const std::vector<Eigen::Vector2d>& points, Eigen::Vector3d* line) {
  if (points.size() < 2) return false;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& p : points) scatter += (p - mean) * (p - mean).transpose();
  if (scatter.trace() <= 1e-12) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
  const Eigen::Vector2d normal = eig.eigenvectors().col(0);  // Smallest eigenvalue.
  *line = Eigen::Vector3d(normal.x(), normal.y(), -normal.dot(mean));
  return true;
}

Status SolveClosedForm(const CorridorObservation& observation, CorridorGeometry* geometry) {
  std::string why;
  if (!observation.Check(&why)) return Status::InvalidArgument(why);
  Eigen::Vector3d left_line, right_line;
  if (!FitImageLine(observation.left, &left_line) || !FitImageLine(observation.right, &right_line)) {
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
  if (!MeanLateralPosition(k, rotation, observation.left, &left_x) ||
      !MeanLateralPosition(k, rotation, observation.right, &right_x)) {
    return Status::ImplausibleGeometry(
        "junction points lie above the horizon of the vanishing point (not on the floor)");
  }
  const double d_left = -left_x, d_right = right_x;
  if (!(d_left > 0 && d_right > 0)) {
    return Status::ImplausibleGeometry("the camera is not between the two junctions");
  }
  geometry->yaw = yaw;
  geometry->pitch = pitch;
  geometry->width = d_left + d_right;
  geometry->offset = 0.5 * (d_left - d_right);
  geometry->camera_height = observation.camera_height;
  return Status::Ok();
}

}  // namespace corridor
