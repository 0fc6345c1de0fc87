#include "estimation/closed_form.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "corridor_depth/corridor_frame.h"
#include "corridor_depth/line_inliers.h"
#include "corridor_depth/virtual_camera.h"

namespace corridor {
namespace {

// Median lateral position X_W of the points' floor intersections, or false if any misses the
// floor.
bool MedianLateralPosition(const FloorIntrinsics& k, const CorridorRotation<double>& rotation,
                           const std::vector<Eigen::Vector2d>& points, double* median_x) {
  // The thread's, reused from call to call.
  thread_local std::vector<double> thread_x;
  std::vector<double>& x = thread_x;
  x.clear();
  for (const auto& p : points) {
    Vec3<double> floor_point;
    if (!BackProjectToFloor(k, rotation, p.x(), p.y(), &floor_point)) return false;
    x.push_back(floor_point.x);
  }
  std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
  *median_x = x[x.size() / 2];
  return true;
}

// The points that lie on their side's dominant line (LineInlierMask), so that gross outliers
// neither tilt the fitted line nor shift the lateral positions.
// Into *inliers, which keeps its memory.
void Inliers(const std::vector<Eigen::Vector2d>& points, std::vector<Eigen::Vector2d>* inliers) {
  thread_local std::vector<char> thread_keep;
  std::vector<char>& keep = thread_keep;
  LineInlierMask(points, &keep);
  inliers->clear();
  for (size_t i = 0; i < points.size(); ++i) {
    if (keep[i]) inliers->push_back(points[i]);
  }
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
  // The thread's, reused from call to call.
  thread_local std::vector<Eigen::Vector2d> thread_left, thread_right;
  std::vector<Eigen::Vector2d>& left = thread_left;
  std::vector<Eigen::Vector2d>& right = thread_right;
  Inliers(observation.left, &left);
  Inliers(observation.right, &right);
  Eigen::Vector3d left_line, right_line;
  if (!FitImageLine(left, &left_line) || !FitImageLine(right, &right_line)) {
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
  if (!MedianLateralPosition(k, rotation, left, &left_x) ||
      !MedianLateralPosition(k, rotation, right, &right_x)) {
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
