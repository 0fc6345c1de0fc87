#pragma once

#include <vector>

#include "corridor_depth/camera.h"

namespace corridor {

// The normalised ray (x, y, 1) of every pixel, with lens distortion removed: computed once per
// camera, it lets the exact rasteriser honour plumb_bob calibrations at no per-frame cost.
class RayTable {
 public:
  explicit RayTable(const Camera& camera);
  int width() const { return width_; }
  int height() const { return height_; }
  // Ray x and y of pixel (u, v).
  float x(int u, int v) const { return x_[static_cast<size_t>(v) * width_ + u]; }
  float y(int u, int v) const { return y_[static_cast<size_t>(v) * width_ + u]; }
  const float* row_x(int v) const { return x_.data() + static_cast<size_t>(v) * width_; }
  const float* row_y(int v) const { return y_.data() + static_cast<size_t>(v) * width_; }
  // True when this table was built for the camera (same size, intrinsics and distortion).
  bool Matches(const Camera& camera) const;

 private:
  Camera camera_;
  int width_, height_;
  std::vector<float> x_, y_;
};

}  // namespace corridor
