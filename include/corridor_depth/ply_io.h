#pragma once

#include <string>

#include "corridor_depth/point_cloud.h"
#include "corridor_depth/status.h"

namespace corridor {

// Writes a PLY point cloud, binary little-endian: `float x, y, z` (metres) and `uchar red, green,
// blue` per vertex, as Open3D, CloudCompare and MeshLab read it. Atomic (temporary name, then
// renamed); creates parent folders. InvalidArgument when xyz and rgb disagree in size.
Status WritePlyAtomic(const std::string& path, const PointCloud& cloud);

}  // namespace corridor
