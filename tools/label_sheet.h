#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "evaluation/junction_labels.h"

namespace corridor {

// One photo of a contact sheet: the photo with its labelled junction segments (green) and the
// junctions the reported geometry projects (red; none when refused; turned by `roll`, the roll the
// frame was recovered level from), a caption below.
cv::Mat LabelTile(const cv::Mat& bgr, const JunctionLabel& label, bool ok,
                  const CorridorGeometry& geometry, double roll, const Camera& camera,
                  const std::string& caption, int tile_width);

// Tiles side by side, `columns` to a row, on a white background.
cv::Mat ContactSheet(const std::vector<cv::Mat>& tiles, int columns);

}  // namespace corridor
