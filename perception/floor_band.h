#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "perception/floor_texture.h"

namespace corridor {

// What is counted in a band (see MeasureBandEdges).
struct BandEdgeOptions {
  double margin = 3.0;           // Band pixels lie this far from both lines and below the vanishing point's row, image px.
  double tolerance_deg = 15;     // An edge within this of horizontal runs across, of vertical stands.
  double vp_tolerance_deg = 10;  // ... unless it runs within this of the direction to the vanishing point.
};

// The edges of a band between two lines through one vanishing point. The floor's edges across the corridor (tile
// joints, a runner's ends) are near horizontal in the image; a wall's (door frames, corners,
// panel joints) are vertical. Both run along the corridor too, toward the vanishing point: those
// are not counted.
struct BandEdges {
  long pixels = 0;      // Gradient-map pixels in the band.
  long across = 0;      // Edge pixels running across (near horizontal).
  int across_rows = 0;  // Gradient-map rows with at least one of them: a floor's joints recur
                        // down the band, a box's front edges are one or two rows.
  long vertical = 0;    // Edge pixels standing vertical.
  long oblique = 0;     // Edge pixels neither across, vertical nor toward the vanishing point: a
                        // carpet's texture has edges in every direction, most of them oblique.
};

// The band above `inner` and below `outer` (normals pointing down, as MergedLine), below the
// vanishing point's row: its edge pixels of `edges` (CV_8U, 255 = edge, on `grid`), classed by
// the gradients `dx`, `dy` (CV_16S, same grid).
BandEdges MeasureBandEdges(const cv::Mat& edges, const cv::Mat& dx, const cv::Mat& dy,
                           const GradientGrid& grid, const Eigen::Vector3d& inner,
                           const Eigen::Vector3d& outer, const Eigen::Vector2d& vanishing_point,
                           const BandEdgeOptions& options);

}  // namespace corridor
