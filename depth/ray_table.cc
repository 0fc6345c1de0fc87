#include "depth/ray_table.h"

#include "corridor_depth/corridor_frame.h"

namespace corridor {

RayTable::RayTable(const Camera& camera)
    : camera_(camera), width_(camera.image_width), height_(camera.image_height) {
  const size_t n = static_cast<size_t>(width_) * height_;
  x_.resize(n);
  y_.resize(n);
  for (int v = 0; v < height_; ++v) {
    for (int u = 0; u < width_; ++u) {
      const Vec3<double> ray = RayOfRawPixel(camera, u, v);
      x_[static_cast<size_t>(v) * width_ + u] = static_cast<float>(ray.x);
      y_[static_cast<size_t>(v) * width_ + u] = static_cast<float>(ray.y);
    }
  }
}

bool RayTable::Matches(const Camera& camera) const {
  return camera.image_width == camera_.image_width &&
         camera.image_height == camera_.image_height && camera.fx == camera_.fx &&
         camera.fy == camera_.fy && camera.cx == camera_.cx && camera.cy == camera_.cy &&
         camera.distortion == camera_.distortion;
}

}  // namespace corridor
