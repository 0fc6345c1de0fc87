#include "pipeline/one_junction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "corridor_depth/corridor_frame.h"

namespace corridor {

Status GeometryFromOneJunction(const JunctionPair& pair, const Camera& camera, double width,
                               const CorridorGeometry* prior, CorridorGeometry* geometry,
                               std::string* how) {
  if (!pair.has_single) return Status::NoCorridorFound("no junction line at all");
  const char* side = pair.single_is_left ? "left" : "right";
  if (!(width > 0)) {
    return Status::NoCorridorFound(std::string("only the ") + side +
                                   " junction is visible and the width is unknown (pass "
                                   "--width_prior=M, or give a sequence)");
  }
  const JunctionLine& line = pair.single;
  double pitch = 0, yaw = 0;
  char text[160];
  if (pair.single_has_vp) {
    // d ~ K^-1 vp = (sin yaw, -sin pitch cos yaw, cos pitch cos yaw).
    const Vec3<double> d = RayOfRawPixel(camera, pair.single_vp.x(), pair.single_vp.y());
    pitch = std::atan2(-d.y, d.z);
    yaw = std::atan2(d.x, std::hypot(d.y, d.z));
    std::snprintf(text, sizeof(text), "vanishing point from %d lines", pair.single_vp_votes);
  } else if (prior != nullptr) {
    // The vanishing point lies on the junction and on the row of the previous pitch.
    pitch = prior->pitch;
    const Vec3<double> a = RayOfRawPixel(camera, line.near_end.x(), line.near_end.y());
    const Vec3<double> b = RayOfRawPixel(camera, line.far_end.x(), line.far_end.y());
    const double y_vp = -std::tan(pitch);  // Normalised y of every direction with this pitch.
    if (std::abs(b.y - a.y) < 1e-9) return Status::NoCorridorFound("the junction is horizontal");
    const double x_vp = a.x + (b.x - a.x) * (y_vp - a.y) / (b.y - a.y);
    // d = (x_vp, y_vp, 1) normalised: sin yaw = d_x.
    yaw = std::atan2(x_vp, std::hypot(y_vp, 1.0));
    std::snprintf(text, sizeof(text), "the previous frame's pitch");
  } else {
    return Status::NoCorridorFound(std::string("only the ") + side +
                                   " junction is visible and no other line gives its vanishing "
                                   "point");
  }
  const CorridorRotation<double> r(pitch, yaw);
  const Vec3<double> n = r.FloorNormal();
  std::vector<double> xs;
  for (const Eigen::Vector2d& p : SampleAlongLine(line, 30)) {
    const Vec3<double> ray = RayOfRawPixel(camera, p.x(), p.y());
    const double nr = Dot(n, ray);
    if (nr <= 1e-6) continue;
    const double z = camera.mount_height / nr;
    xs.push_back(r.ToCorridor({z * ray.x, z * ray.y, z * ray.z}).x);
  }
  if (xs.size() < 5) return Status::NoCorridorFound("the junction does not meet the floor");
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  const double x = xs[xs.size() / 2];
  const double near = pair.single_is_left ? -x : x;  // Distance to the visible wall.
  if (!(near > 0.05 && near < width - 0.05)) {
    std::snprintf(text, sizeof(text), "the %s wall at %.2f m does not fit a %.2f m corridor", side,
                  near, width);
    return Status::ImplausibleGeometry(text);
  }
  CorridorGeometry g;
  g.pitch = pitch;
  g.yaw = yaw;
  g.width = width;
  g.camera_height = camera.mount_height;
  const double far = width - near;
  g.offset = pair.single_is_left ? 0.5 * (near - far) : 0.5 * (far - near);  // (d_l - d_r) / 2.
  *geometry = g;
  char summary[240];
  std::snprintf(summary, sizeof(summary), "%s junction only: width %.2f m, %s", side, width, text);
  *how = summary;
  return Status::Ok();
}

}  // namespace corridor
