#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/junction_lines.h"

namespace corridor {

struct JunctionEdgePointOptions {
  double reach_px = 2;         // Edge peaks are sought this far from the fitted line along each row (column), px, either side.
  double max_distance_px = 1;  // Peaks farther than this from the fitted line (perpendicular) are dropped, px: a baseboard's top a few pixels above the junction is not taken for it.
  double threshold = 15;       // Least colour gradient across the line (Sobel 3x3, the strongest channel) of a peak: low, so that a faint junction under a strong edge (a floor meeting a dark baseboard) keeps its own peak, the nearest.
  double weight_power = 2;     // A point's weight is (strength / median strength)^weight_power: 2 = inverse variance, 0 = all alike.
  double max_weight = 4;       // A point's weight is at most this many times the median point's.

  bool Check(std::string* why) const;
};

// The junction's measured edge points with weights, into line->edge_points (raw pixels) and
// line->edge_weights. On each row (column, for lines flatter than 45 degrees) that holds a support
// pixel (or is next to one), the peak of the colour gradient across the fitted line nearest that
// line, placed to sub-pixel precision by a parabola through the peak and its two neighbours along
// the row (EdgePeaksAlong): the integer Canny pixels, biased by up to half a pixel and on both
// sides of a blurred edge, become one point per row where the edge is. A point's weight is the
// inverse of its position's expected variance, which falls with the square of the gradient across
// the edge: (strength / median strength)^weight_power (2), at most max_weight, so that a few very strong pixels
// (another line's crossing) cannot outweigh the junction. Weights are scaled to a mean of 1.
// Both vectors are emptied when fewer than two points are found.
void MeasureJunctionEdgePoints(const cv::Mat& bgr, const JunctionEdgePointOptions& options,
                               JunctionLine* line);

}  // namespace corridor
