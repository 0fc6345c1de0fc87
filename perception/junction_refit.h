#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/junction_lines.h"

namespace corridor {

struct JunctionRefitOptions {
  double reach_px = 4;             // Edge points are sought this far from the coarse line, px (either side).
  double threshold = 40;           // Least colour gradient across the line (Sobel 3x3, the strongest channel) of an edge point.
  double support_distance_px = 2;  // Points this close to a fit are kept for the next fit, px.
  int step_px = 1;                 // An edge point is sought on every this many rows (columns).
};

// Refits a junction found at a coarser working resolution on the full-resolution image `bgr`
// (8-bit, 3 channels): at every step_px-th row (column, for lines flatter than 45 degrees) between
// the line's two ends, the point nearest the line, within reach, where the colour gradient across the
// line peaks above the threshold (to a tenth of a pixel, by a parabola through the peak and its
// neighbours); then the line of least distance to those points, and again to the points within
// support_distance_px of it. The ends are projected onto the new line and the
// support replaced by the points. False, and *line untouched, with fewer than eight points or no
// fit (a line of too little contrast at full resolution keeps its coarse fit).
bool RefitJunctionAtFullResolution(const cv::Mat& bgr, const JunctionRefitOptions& options,
                                   JunctionLine* line);

}  // namespace corridor
