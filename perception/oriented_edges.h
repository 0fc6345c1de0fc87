#pragma once

// Private helper of the ceiling search: colour edges that know which way they run, and how well a
// projected line follows them.

#include <opencv2/core.hpp>

namespace corridor {

// Canny edges of the colour gradient on the image rows [top, bottom), each with its orientation.
struct OrientedEdges {
  int top = 0;      // First image row of the band.
  cv::Mat edges;    // CV_8U, 255 = edge (band rows).
  cv::Mat near;     // CV_8U: bit b set where an edge of orientation bin b lies within 1 px.
};

// Edges of rows [top, bottom) (clamped to the image), computed with a few rows of margin so that
// the blur and Canny's hysteresis see nearly what they would see over the whole image. Colour
// edges: a green wall under a grey ceiling has hardly any grey edge.
OrientedEdges ComputeOrientedEdges(const cv::Mat& bgr, int top, int bottom);

// Fraction of the line's visible samples (x >= 0; rows inside the band) that have an edge within
// 1 px running along the line: its gradient within one orientation bin (22.5 degrees) of the
// line's normal, so that crossing edges (lights, door frames, clutter) do not count. The fraction
// is of at least half of `samples`, so that a line with few visible samples (one that leaves the
// image near the vanishing point, where every edge converges) cannot score high. 0 with fewer
// than 8 visible samples.
double OrientedLineSupport(const cv::Point* line, int samples, const OrientedEdges& edges);

}  // namespace corridor
