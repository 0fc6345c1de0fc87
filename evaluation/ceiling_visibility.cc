#include "evaluation/ceiling_visibility.h"

#include <algorithm>
#include <cmath>

#include "corridor_depth/corridor_frame.h"

namespace corridor {
namespace {

// Image distance between neighbouring samples along the junction, px (at most).
constexpr double kStepPixels = 0.25;
// At most this many samples (a junction nearly through the camera centre).
constexpr int kMaxSamples = 400000;

bool InsideImage(const Eigen::Vector2d& p, const Camera& camera) {
  return p.x() >= 0 && p.y() >= 0 && p.x() <= camera.image_width - 1 &&
         p.y() <= camera.image_height - 1;
}

}  // namespace

double VisibleCeilingJunctionLength(const CorridorGeometry& truth, const Camera& camera, int side,
                                    const CeilingVisibilityOptions& options) {
  if (!truth.HasCeiling() || !(truth.width > 0) || !std::isfinite(truth.yaw) ||
      !std::isfinite(truth.pitch) || !std::isfinite(truth.offset) ||
      !(options.max_depth > 0) || camera.image_width <= 0 || camera.image_height <= 0 ||
      !(camera.fx > 0) || !(camera.fy > 0)) {
    return 0;
  }
  const double x = side < 0 ? -truth.LeftDistance() : truth.RightDistance();
  const double y = truth.camera_height - truth.ceiling_height;
  const double far = truth.HasEndWall() ? std::min(truth.end_distance, options.max_depth)
                                        : options.max_depth;
  const CorridorRotation<double> rotation(truth.pitch, truth.yaw);
  // Z is sampled uniformly in s = 1/Z (image positions move nearly linearly in s), from `far` to
  // a near limit where the point is far outside the image: the junction's lateral and vertical
  // offsets then exceed three image sizes.
  const double focal = std::max(camera.fx, camera.fy);
  const double lever = std::max({std::abs(x), std::abs(y), 1e-3});
  const double s_far = 1.0 / far;
  const double s_near =
      s_far + 3.0 * std::max(camera.image_width, camera.image_height) /
                  (std::min(camera.fx, camera.fy) * lever);
  const int samples = static_cast<int>(std::min<double>(
      kMaxSamples, std::ceil((s_near - s_far) * focal * std::hypot(x, y) / kStepPixels) + 1));
  double length = 0;
  bool have_previous = false;
  Eigen::Vector2d previous = Eigen::Vector2d::Zero();
  for (int i = 0; i <= samples; ++i) {
    const double inverse = s_far + (s_near - s_far) * i / samples;
    const Vec3<double> c = rotation.ToCamera({x, y, 1.0 / inverse});
    bool inside = false;
    Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
    if (c.z > 1e-6) {
      const Eigen::Vector2d ideal = camera.Project({c.x, c.y, c.z});
      // Far outside the image, the distortion polynomial can fold a point back in: such points
      // are outside whatever the lens does.
      if (std::abs(ideal.x() - camera.cx) < 2.0 * camera.image_width &&
          std::abs(ideal.y() - camera.cy) < 2.0 * camera.image_height) {
        pixel = camera.Distort(ideal);
        inside = InsideImage(pixel, camera);
      }
    }
    if (inside && have_previous) length += (pixel - previous).norm();
    have_previous = inside;
    if (inside) previous = pixel;
  }
  return length;
}

bool CeilingJunctionVisible(const CorridorGeometry& truth, const Camera& camera,
                            const CeilingVisibilityOptions& options) {
  const double needed =
      options.min_length_fraction * std::min(camera.image_width, camera.image_height);
  return std::max(VisibleCeilingJunctionLength(truth, camera, -1, options),
                  VisibleCeilingJunctionLength(truth, camera, +1, options)) >= needed &&
         needed > 0;
}

}  // namespace corridor
