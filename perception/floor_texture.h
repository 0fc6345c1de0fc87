#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace corridor {

// Where a gradient map lies in the image: its pixel (i, j) is image pixel
// (scale * i, first_row + scale * j).
struct GradientGrid {
  int scale = 1;      // Image pixels per gradient-map pixel.
  int first_row = 0;  // Image row of the map's row 0.
};

// What is counted (see MeasureFloorTexture).
struct FloorTextureOptions {
  double margin = 3.0;             // Floor pixels lie this far below both junctions and the vanishing point's row, image px.
  int strong = 240;                // A strong edge: colour |dx| + |dy| (Sobel 3x3) at least this.
  double line_tolerance_deg = 15;  // Edges within this of horizontal, vertical or the direction to the vanishing point are corridor lines.
};

// How much of the floor is strong edges that no corridor line explains. A corridor floor is one
// material: its strong edges are tile joints and tape along the corridor (toward the vanishing
// point), joints across it (near horizontal), and reflections of door frames (vertical); the
// region between two lines of an outdoor scene, a still life or a textured wall has strong edges
// in every direction.
struct FloorTexture {
  long floor_pixels = 0;         // Gradient-map pixels counted as floor.
  double strong_fraction = 0.0;  // The fraction of them whose |dx| + |dy| is at least `strong`.
  double odd_fraction = 0.0;     // ... and whose edge is none of the corridor's line directions.
};

// The floor: pixels below both junction lines (normals pointing down, as JunctionLine) and below
// the vanishing point's row, each by more than the margin. `dx`, `dy`: CV_16S colour gradients (as
// ColorGradient); an edge runs across its gradient.
FloorTexture MeasureFloorTexture(const cv::Mat& dx, const cv::Mat& dy, const GradientGrid& grid,
                                 const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                                 const Eigen::Vector2d& vanishing_point,
                                 const FloorTextureOptions& options);

}  // namespace corridor
