#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "corridor_depth/corridor_frame.h"
#include "corridor_depth/corridor_geometry.h"

namespace corridor {

// Which surface of the box model a ray meets first (docs/geometry.md s3 and s6, plus the end wall
// when known), for the per-pixel masks. The exact rasteriser has its own vectorised row loop.
enum class BoxSurface { kNone,
                        kFloor,
                        kWall,
                        kCeiling,
                        kEndWall };

struct BoxHit {
  BoxSurface surface = BoxSurface::kNone;              // The first surface met.
  double z = std::numeric_limits<double>::infinity();  // Its depth along the ray (camera z).
};

// The box's normals and axis in the camera frame, computed once per geometry.
struct BoxFrame {
  explicit BoxFrame(const CorridorGeometry& g) : geometry(g) {
    const CorridorRotation<double> r(g.pitch, g.yaw);
    n = r.FloorNormal();
    m = r.WallNormal();
    d = r.Axis();
  }
  const CorridorGeometry& geometry;
  Vec3<double> n, m, d;  // Floor normal, wall normal, corridor axis.
};

// The first surface the ray (x, y, 1) meets. Ties go to the later surface in the order floor,
// wall, ceiling; the end wall must be strictly nearer than all of them.
inline BoxHit FirstBoxSurface(const BoxFrame& box, const Vec3<double>& ray) {
  const CorridorGeometry& g = box.geometry;
  const double inf = std::numeric_limits<double>::infinity();
  const double nr = Dot(box.n, ray), mr = Dot(box.m, ray), dr = Dot(box.d, ray);
  const double z_floor = nr > 0 ? g.camera_height / nr : inf;
  const double z_wall = mr < 0 ? -g.LeftDistance() / mr : (mr > 0 ? g.RightDistance() / mr : inf);
  const double z_ceiling =
      g.HasCeiling() && nr < 0 ? (g.camera_height - g.ceiling_height) / nr : inf;
  if (g.HasEndWall() && dr > 0 && g.end_distance / dr < std::min({z_floor, z_wall, z_ceiling})) {
    return {BoxSurface::kEndWall, g.end_distance / dr};
  }
  if (z_floor < z_wall && z_floor < z_ceiling) return {BoxSurface::kFloor, z_floor};
  if (z_wall < z_ceiling && std::isfinite(z_wall)) return {BoxSurface::kWall, z_wall};
  if (std::isfinite(z_ceiling)) return {BoxSurface::kCeiling, z_ceiling};
  return {};
}

}  // namespace corridor
