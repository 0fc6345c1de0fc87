#pragma once

// The corridor frame W and the camera frame C of docs/geometry.md, section 2, as templated helpers
// so that Ceres' Jets flow through them. P_C = R P_W with R = R_x(pitch) R_y(yaw).

#include <cmath>

#include "corridor_depth/camera.h"

namespace corridor {

template <typename T>
struct Vec3 {
  T x, y, z;
};

template <typename T>
inline T Dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// The rotation R = R_x(pitch) R_y(yaw), stored by rows; columns are the corridor axes in C.
template <typename T>
struct CorridorRotation {
  T m[3][3];

  CorridorRotation(const T& pitch, const T& yaw) {
    using std::cos;
    using std::sin;
    const T ct = cos(pitch), st = sin(pitch), cp = cos(yaw), sp = sin(yaw);
    m[0][0] = cp;
    m[0][1] = T(0);
    m[0][2] = sp;
    m[1][0] = st * sp;
    m[1][1] = ct;
    m[1][2] = -st * cp;
    m[2][0] = -ct * sp;
    m[2][1] = st;
    m[2][2] = ct * cp;
  }
  // Wall normal m = R e_x.
  Vec3<T> WallNormal() const { return {m[0][0], m[1][0], m[2][0]}; }
  // Floor normal n = R e_y (pointing down).
  Vec3<T> FloorNormal() const { return {m[0][1], m[1][1], m[2][1]}; }
  // Corridor direction d = R e_z.
  Vec3<T> Axis() const { return {m[0][2], m[1][2], m[2][2]}; }
  // P_C = R P_W.
  Vec3<T> ToCamera(const Vec3<T>& w) const {
    return {m[0][0] * w.x + m[0][1] * w.y + m[0][2] * w.z,
            m[1][0] * w.x + m[1][1] * w.y + m[1][2] * w.z,
            m[2][0] * w.x + m[2][1] * w.y + m[2][2] * w.z};
  }
  // P_W = R^T P_C.
  Vec3<T> ToCorridor(const Vec3<T>& c) const {
    return {m[0][0] * c.x + m[1][0] * c.y + m[2][0] * c.z,
            m[0][1] * c.x + m[1][1] * c.y + m[2][1] * c.z,
            m[0][2] * c.x + m[1][2] * c.y + m[2][2] * c.z};
  }
};

// A point of a level camera's frame as the same camera turned by `roll` about its optical axis
// sees it: R_z(roll) c, R_z(r) = [cos r, -sin r, 0; sin r, cos r, 0; 0, 0, 1]. A frame recovered
// level (RecoverDepthResult::roll) has its geometry in the level camera: this puts the geometry's
// points back into the frame's own camera.
inline Vec3<double> TurnedByRoll(const Vec3<double>& c, double roll) {
  const double cr = std::cos(roll), sr = std::sin(roll);
  return {cr * c.x - sr * c.y, sr * c.x + cr * c.y, c.z};
}

// The normalised ray (x, y, 1) of a raw image pixel, lens distortion removed.
inline Vec3<double> RayOfRawPixel(const Camera& camera, double u, double v) {
  const Eigen::Vector2d ideal = camera.Undistort({u, v});
  return {(ideal.x() - camera.cx) / camera.fx, (ideal.y() - camera.cy) / camera.fy, 1.0};
}

}  // namespace corridor
