#include "corridor_depth/corridor_geometry.h"

#include <cstdio>

namespace corridor {

std::string CorridorGeometry::ToString() const {
  char buffer[200];
  std::snprintf(buffer, sizeof(buffer),
                "yaw=%.4f rad, pitch=%.4f rad, offset=%.3f m, width=%.3f m, h=%.3f m, "
                "ceiling=%.3f m, end wall=%.3f m",
                yaw, pitch, offset, width, camera_height, ceiling_height, end_distance);
  return buffer;
}

}  // namespace corridor
