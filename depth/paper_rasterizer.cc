#include "depth/paper_rasterizer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "corridor_depth/corridor_frame.h"

namespace corridor {
namespace {

// One projected vertex of a depth plane's polyline.
struct Vertex {
  double u, v, z;  // Ideal pixel and camera-frame depth.
};

// Ideal pixel and camera depth of a corridor-frame point.
Vertex ProjectPoint(const CorridorRotation<double>& r, const Camera& camera, double x, double y,
                    double z) {
  const Vec3<double> c = r.ToCamera({x, y, z});
  return {camera.fx * c.x / c.z + camera.cx, camera.fy * c.y / c.z + camera.cy, c.z};
}

// A region between two image lines through the vanishing point: the cone (one of four) that
// holds a reference point.
struct Cone {
  Eigen::Vector3d a, b;  // Lines, oriented so that the reference point is on their positive side.

  Cone(const Vertex& p0, const Vertex& p1, const Vertex& q0, const Vertex& q1, const Vertex& ref) {
    a = Eigen::Vector3d(p0.u, p0.v, 1).cross(Eigen::Vector3d(p1.u, p1.v, 1));
    b = Eigen::Vector3d(q0.u, q0.v, 1).cross(Eigen::Vector3d(q1.u, q1.v, 1));
    if (a.dot(Eigen::Vector3d(ref.u, ref.v, 1)) < 0) a = -a;
    if (b.dot(Eigen::Vector3d(ref.u, ref.v, 1)) < 0) b = -b;
  }
  bool Contains(double u, double v) const {
    return a.x() * u + a.y() * v + a.z() >= 0 && b.x() * u + b.y() * v + b.z() >= 0;
  }
};

double Lerp(double a, double b, double t) { return a + t * (b - a); }

// The point of segment p->q at parameter coordinate `at` along axis (0: u, 1: v), with depth
// interpolated linearly along that axis (the paper's linear interpolation).
bool AlongSegment(const Vertex& p, const Vertex& q, int axis, double at, double* other,
                  double* z) {
  const double p_at = axis == 0 ? p.u : p.v, q_at = axis == 0 ? q.u : q.v;
  if (std::abs(q_at - p_at) < 1e-9) return false;
  const double t = (at - p_at) / (q_at - p_at);
  *other = axis == 0 ? Lerp(p.v, q.v, t) : Lerp(p.u, q.u, t);
  *z = Lerp(p.z, q.z, t);
  return std::isfinite(*other) && std::isfinite(*z);  // Not for vertices at infinity (or NaN).
}

// x rounded by `round` (std::ceil or std::floor) and clamped to [lo, hi], clamped before the
// conversion to int (which is undefined for values out of int's range).
template <typename Round>
int RoundedIndex(double x, Round round, int lo, int hi) {
  return static_cast<int>(std::clamp(round(x), static_cast<double>(lo), static_cast<double>(hi)));
}

// Smallest Z_W at which every polyline vertex lies at least 5 cm in front of the camera.
double NearestPlane(const CorridorRotation<double>& r, double x_left, double x_right, double y_floor,
                    double y_top) {
  double z_near = 0.3;
  for (double x : {x_left, x_right}) {
    for (double y : {y_floor, y_top}) {
      const Vec3<double> c0 = r.ToCamera({x, y, 0.0});
      const double per_z = r.m[2][2];  // d(camera z)/d(Z_W)
      if (per_z > 1e-6) z_near = std::max(z_near, (0.05 - c0.z) / per_z);
    }
  }
  return z_near;
}

}  // namespace

Status PaperRasterizer::Render(const CorridorGeometry& geometry, const Camera& camera,
                               cv::Mat* depth) const {
  std::string why;
  if (!camera.CheckIntrinsics(&why)) return Status::InvalidArgument("camera: " + why);
  const Status valid = CheckGeometryForRendering(geometry);
  if (!valid.ok()) return valid;
  const int width = camera.image_width, height = camera.image_height;
  *depth = cv::Mat::zeros(height, width, CV_32F);
  const CorridorRotation<double> r(geometry.pitch, geometry.yaw);
  if (r.m[2][2] < 1e-3) return Status::ImplausibleGeometry("corridor axis is not in front of the camera");

  const double h = geometry.camera_height;
  const double top = options_.use_ceiling && geometry.HasCeiling() ? geometry.ceiling_height
                                                                   : options_.max_height;
  const double y_top = h - top;
  const double x_left = -geometry.LeftDistance(), x_right = geometry.RightDistance();
  const double z_near = NearestPlane(r, x_left, x_right, h, y_top);
  const double z_far = options_.max_range;
  if (!(z_near < z_far)) return Status::Ok();  // Nothing within range.

  // The planes, uniform in inverse depth (roughly uniform in image rows).
  const int k_count = options_.paper_planes;
  std::vector<Vertex> left(k_count), right(k_count), left_top(k_count), right_top(k_count);
  for (int k = 0; k < k_count; ++k) {
    const double z = 1.0 / Lerp(1.0 / z_near, 1.0 / z_far, k / (k_count - 1.0));
    left[k] = ProjectPoint(r, camera, x_left, h, z);
    right[k] = ProjectPoint(r, camera, x_right, h, z);
    left_top[k] = ProjectPoint(r, camera, x_left, y_top, z);
    right_top[k] = ProjectPoint(r, camera, x_right, y_top, z);
  }
  const int mid = k_count / 2;
  const Vertex floor_ref = ProjectPoint(r, camera, 0.5 * (x_left + x_right), h, 5.0);
  const Vertex left_ref = ProjectPoint(r, camera, x_left, 0.5 * (h + y_top), 5.0);
  const Vertex right_ref = ProjectPoint(r, camera, x_right, 0.5 * (h + y_top), 5.0);
  const Cone floor_cone(left[0], left[mid], right[0], right[mid], floor_ref);
  const Cone left_cone(left[0], left[mid], left_top[0], left_top[mid], left_ref);
  const Cone right_cone(right[0], right[mid], right_top[0], right_top[mid], right_ref);

  // Floor: per column, between consecutive floor segments (eq. 21: linear in v).
  for (int u = 0; u < width; ++u) {
    for (int k = 1; k < k_count; ++k) {
      double v_near, z_near_seg, v_far, z_far_seg;
      if (!AlongSegment(left[k - 1], right[k - 1], 0, u, &v_near, &z_near_seg) ||
          !AlongSegment(left[k], right[k], 0, u, &v_far, &z_far_seg) || v_near <= v_far) {
        continue;
      }
      const int v0 = RoundedIndex(
          v_far, [](double x) { return std::ceil(x); }, 0, height);
      const int v1 = RoundedIndex(
          v_near, [](double x) { return std::floor(x); }, -1, height - 1);
      for (int v = v0; v <= v1; ++v) {
        if (!floor_cone.Contains(u, v)) continue;
        const double sigma = (v_near - v) / (v_near - v_far);
        depth->at<float>(v, u) = static_cast<float>(Lerp(z_near_seg, z_far_seg, sigma));
      }
    }
  }
  // Walls: per row, between consecutive wall segments (eq. 22: linear in u).
  for (int v = 0; v < height; ++v) {
    for (int side = 0; side < 2; ++side) {
      const auto& bottom = side == 0 ? left : right;
      const auto& upper = side == 0 ? left_top : right_top;
      const Cone& cone = side == 0 ? left_cone : right_cone;
      for (int k = 1; k < k_count; ++k) {
        double u_near, z_near_seg, u_far, z_far_seg;
        if (!AlongSegment(bottom[k - 1], upper[k - 1], 1, v, &u_near, &z_near_seg) ||
            !AlongSegment(bottom[k], upper[k], 1, v, &u_far, &z_far_seg) ||
            std::abs(u_near - u_far) < 1e-9) {
          continue;
        }
        const int u0 = RoundedIndex(
            std::min(u_near, u_far), [](double x) { return std::ceil(x); },
            0, width);
        const int u1 = RoundedIndex(
            std::max(u_near, u_far), [](double x) { return std::floor(x); },
            -1, width - 1);
        for (int u = u0; u <= u1; ++u) {
          if (!cone.Contains(u, v)) continue;
          const double sigma = (u - u_near) / (u_far - u_near);
          depth->at<float>(v, u) = static_cast<float>(Lerp(z_near_seg, z_far_seg, sigma));
        }
      }
    }
  }
  return Status::Ok();
}

}  // namespace corridor
