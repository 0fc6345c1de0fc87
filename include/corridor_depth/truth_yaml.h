#pragma once

#include <string>
#include <vector>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"

namespace corridor {

// One frame's true geometry: truth.yaml's `frames:` list entries
// {file, pitch, yaw, offset, width, camera_height, ceiling_height}, radians and metres.
struct FrameTruth {
  std::string file;           // The colour image's file name, e.g. "000003.png".
  CorridorGeometry geometry;  // Signs as in docs/geometry.md.
};

Status ReadTruthYaml(const std::string& path, std::vector<FrameTruth>* frames);
Status WriteTruthYaml(const std::string& path, const std::vector<FrameTruth>& frames);

}  // namespace corridor
