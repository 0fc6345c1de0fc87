#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/corridor_geometry.h"
#include "core/status.h"
#include "perception/oriented_edges.h"

namespace corridor {

// Finding the ceiling height once the walls are known (beyond the paper; docs/geometry.md s6).
struct CeilingDetectorOptions {
  double min_height = 1.8;             // Lowest ceiling considered, m above the floor.
  double max_height = 6.0;             // Highest ceiling considered, m above the floor.
  double step = 0.01;                  // Search step of the ceiling height, m.
  double near_distance = 1.0;          // Junction samples from this distance along the corridor, m...
  double far_distance = 30.0;          // ... to this one.
  int samples = 80;                    // Samples per junction line.
  double min_support = 0.35;           // Fraction of a line's visible samples on edges to accept it.
  double min_counted_fraction = 0.25;  // ... counting at least this fraction of `samples` as visible (a high ceiling, or a narrow vertical field of view, shows its junction only from a few metres on).

  bool Check(std::string* why) const;
};

struct CeilingEstimate {
  bool found = false;        // True when at least one ceiling/wall junction was seen.
  double height = 0;         // H_c, m above the floor (valid when found).
  double left_support = 0;   // Fraction of the left junction's visible samples on edges (at least min_counted_fraction of the samples counted).
  double right_support = 0;  // Same for the right one.
  int points = 0;            // Edge pixels whose rays gave the robust (median) estimate.
  // Each side searched alone: the height whose junction on that wall best follows the edges, and
  // its support. A wrong wall distance scales its side's height, so the two then disagree.
  double side_height[2] = {0, 0};           // Left, right: H_c, m (0 when the side has no line).
  double side_support[2] = {0, 0};          // Left, right: the support of that line (of at least half the samples, as the search counts).
  double side_visible_support[2] = {0, 0};  // Left, right: the same line's support on its samples in view (at least min_counted_fraction counted, as the chosen lines are judged).
  std::string reason;                       // Why nothing was found.
};

// Searches the ceiling height whose two ceiling/wall junctions, (-d_l, h - H_c, Z) and
// (d_r, h - H_c, Z), best follow the image's edges; then each edge pixel near the chosen lines
// gives H_c from its ray's intersection with its wall plane, and the median is the estimate.
// `bgr` is the raw image; the camera's distortion is honoured. Never fails on bad images:
// estimate->found is false with a reason. `edges`: null, or the frame's edges of `bgr` shared by
// its searches (ComputeImageEdges, or empty at first), used where they cover the rows searched
// and otherwise filled from the top down far enough (ComputeOrientedEdges).
Status DetectCeiling(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& geometry,
                     const CeilingDetectorOptions& options, CeilingEstimate* estimate,
                     ImageEdges* edges = nullptr);

// Fraction of the corridor line (x, y, Z) (a wall's junction with the floor at y = camera height,
// or with the ceiling) on edges of its orientation, its samples taken as the ceiling search takes
// them (options.samples, near_distance to far_distance, evenly in inverse distance) and judged as
// it judges its chosen lines: over the samples in view, at least min_counted_fraction counted.
// `edges` as for DetectCeiling, extended down to the line's rows. 0 when no sample is in view.
double CorridorLineSupport(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g,
                           double x, double y, const CeilingDetectorOptions& options,
                           ImageEdges* edges = nullptr);

}  // namespace corridor
