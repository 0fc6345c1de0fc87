#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "perception/oriented_edges.h"
#include "corridor_depth/stage_options.h"
#include "corridor_depth/stage_results.h"

namespace corridor {

// Searches the end wall's distance; then each edge pixel near the chosen floor/end-wall line
// gives D from its ray's intersection with the floor, and the median is the estimate. `bgr` is
// the raw image; the camera's distortion is honoured. Never fails on bad images: found is false
// with a reason. InvalidArgument for bad options or an image that is not the camera's size.
// `edges`: the image's edges when another search has them (ComputeImageEdges of `bgr`, or its top
// rows), used when the image is searched at its own resolution; else computed here, the halving
// reusing their blurred rows, for the rows the search looks at only (for an undistorted camera:
// those below the horizon, and above it as far up as the corners of the candidates it examines).
Status DetectEndWall(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& geometry,
                     const EndWallDetectorOptions& options, EndWallEstimate* estimate,
                     const ImageEdges* edges = nullptr);

}  // namespace corridor
