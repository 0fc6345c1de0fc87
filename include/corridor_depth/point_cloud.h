#pragma once

#include <cstdint>
#include <vector>

namespace corridor {

// Points in the camera frame (x right, y down, z forward; metres) with their colours.
struct PointCloud {
  std::vector<float> xyz;    // x0 y0 z0 x1 y1 z1 ...
  std::vector<uint8_t> rgb;  // r0 g0 b0 r1 g1 b1 ... (same count as xyz), 0 when unknown.
  size_t size() const { return xyz.size() / 3; }
};

}  // namespace corridor
