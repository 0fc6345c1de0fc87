#pragma once

// The virtual camera of docs/geometry.md, section 5 (paper III-B): on the corridor's centre line
// (X_W = -offset), at the same height and pitch, with zero yaw. It maps a real-image floor point
// to the virtual image. Templated so that Ceres' Jets pass through.

#include "corridor_depth/corridor_frame.h"

namespace corridor {

// Pinhole intrinsics and camera height, fixed during a solve.
struct FloorIntrinsics {
  double fx, fy, cx, cy;  // Pixels.
  double height;          // h, metres.
};

// The floor point seen at pixel (u, v) in the corridor frame: P_W = (h / n.r) R^T r.
// Returns false when the ray does not meet the floor in front of the camera.
template <typename T>
bool BackProjectToFloor(const FloorIntrinsics& k, const CorridorRotation<T>& rotation, double u,
                        double v, Vec3<T>* floor_point) {
  const Vec3<T> ray{T((u - k.cx) / k.fx), T((v - k.cy) / k.fy), T(1.0)};
  const T n_dot_r = Dot(rotation.FloorNormal(), ray);
  if (!(n_dot_r > T(1e-9))) return false;
  const T z = T(k.height) / n_dot_r;
  *floor_point = rotation.ToCorridor(Vec3<T>{z * ray.x, z * ray.y, z * ray.z});
  return true;
}

// Maps real pixel (u, v) of a floor point to the virtual image (u_V, v_V):
//   P_V = R_x(pitch) (P_W + offset e_x),  p_V = K P_V / Z_V.
template <typename T>
bool MapToVirtualImage(const FloorIntrinsics& k, const CorridorRotation<T>& rotation,
                       const T& pitch, const T& offset, double u, double v, T* u_v, T* v_v) {
  Vec3<T> p;
  if (!BackProjectToFloor(k, rotation, u, v, &p)) return false;
  using std::cos;
  using std::sin;
  const T c = cos(pitch), s = sin(pitch);
  const T x_v = p.x + offset;
  const T y_v = c * p.y - s * p.z;
  const T z_v = s * p.y + c * p.z;
  if (!(z_v > T(1e-9))) return false;
  *u_v = T(k.cx) + T(k.fx) * x_v / z_v;
  *v_v = T(k.cy) + T(k.fy) * y_v / z_v;
  return true;
}

}  // namespace corridor
