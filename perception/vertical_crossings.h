#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/stage_options.h"
#include "corridor_depth/stage_results.h"

namespace corridor {

// The crossings of the floor/wall junction that `geometry` puts on a wall, over the extent of
// `line` (raw pixels of the full image; `scale` full-image pixels per pixel of `bgr`), in the
// 8-bit BGR `bgr` seen by `camera` (of bgr's size). The gradients are computed only on the bands
// examined (a few thousand pixels), from the colour image's channel sum.
VerticalCrossings CountVerticalCrossings(const cv::Mat& bgr, const Camera& camera, int scale,
                                         const CorridorGeometry& geometry, const JunctionLine& line,
                                         const VerticalCrossingOptions& options);

}  // namespace corridor
