#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"

namespace corridor {

struct ConfidenceOptions {
  double floor_color_sigmas = 4.0;   // Floor or wall pixels farther than this many spreads from the surface's colour are objects.
  double min_floor_distance = 12.0;  // ... and at least this far (8-bit Lab units).
  double vertical_edge_deg = 12.0;   // Wall edges within this angle of vertical are doors, frames, objects.
  int edge_margin_px = 4;            // Untrusted band around such edges, px.
};

// Which pixels the box model explains (beyond the paper): 255 = trusted, 0 = not (and 0 where
// `depth` has no estimate). Floor and wall pixels whose colour (5x5 median) differs from their
// surface's median colour (objects, people, doors, furniture; the wall's lowest 0.2 m, the
// baseboard, is not tested), and wall pixels near near-vertical edges (door frames, pillars),
// are not trusted. The depth there stays the model's; the mask lets a robot or an evaluation tell them
// apart. `bgr` is the 8-bit frame, `depth` the rasterised depth of `geometry`.
cv::Mat ComputeConfidenceMask(const cv::Mat& bgr, const cv::Mat& depth, const Camera& camera,
                              const CorridorGeometry& geometry,
                              const ConfidenceOptions& options = ConfidenceOptions());

}  // namespace corridor
