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

// How much of the floor is strong edges: a corridor floor is one material, so high-contrast edges
// are rare on it (tile joints, reflections and shadows are faint), while the region between two
// lines of an outdoor scene, a still life or a textured wall is full of them.
struct FloorTexture {
  long floor_pixels = 0;         // Gradient-map pixels counted as floor.
  double strong_fraction = 0.0;  // The fraction of them whose |dx| + |dy| is at least `strong`.
};

// The floor: pixels below both junction lines (normals pointing down, as JunctionLine) by more
// than `margin` image px, and below the vanishing point's row by as much. `dx`, `dy`: CV_16S
// colour gradients (as ColorGradient). A strong edge: |dx| + |dy| >= strong.
FloorTexture MeasureFloorTexture(const cv::Mat& dx, const cv::Mat& dy, const GradientGrid& grid,
                                 const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                                 double vanishing_row, double margin, int strong);

}  // namespace corridor
