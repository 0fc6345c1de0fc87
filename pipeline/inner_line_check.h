#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/corridor_geometry.h"
#include "perception/ceiling_detector.h"

namespace corridor {

// A junction taken from a line inside the floor (a grout line, a box's bottom edge, a rug's edge:
// all parallel to the corridor, so the vanishing point, yaw and pitch stay right) puts its wall
// too near, by the same factor as the height of the ceiling its own ceiling/wall junction gives:
// the ceiling junctions, each searched alone over a wide range of heights, then disagree, and the
// side with the lower ceiling is the one too near. That wall is moved out, by the ratio of the two
// heights, to where its ceiling junction meets the other side's ceiling.
struct InnerLineCheckOptions {
  double min_disagreement = 0.15;  // Least relative difference of the two sides' ceiling heights that moves a wall.
  double min_support = 0.35;       // Least fraction of each side's ceiling junction on edges (the ceiling search's own minimum).
  double min_above_camera = 0.2;   // The wide search: ceilings from this far above the camera, m, up to the ceiling search's max_height.

  bool Check(std::string* why) const;
};

struct InnerLineCheck {
  bool moved = false;           // True when a wall was moved (geometry updated).
  int side = -1;                // The wall moved: 0 left, 1 right.
  double factor = 1;            // Its distance was multiplied by this (> 1).
  double side_height[2] = {0, 0};   // The wide search's ceiling height per side, m (0 = none).
  double side_support[2] = {0, 0};  // Their supports.
};

// Runs the check on the search image (`bgr` with `camera`, as the ceiling search sees them);
// `ceiling` are the ceiling search's options (its min_height..max_height bound the ceiling the
// trusted side may give). Updates *geometry (width and offset) when a wall moves. `edges`: the
// frame's edges of the search image (see DetectCeiling), or null.
InnerLineCheck CheckInnerLine(const cv::Mat& bgr, const Camera& camera,
                              const CeilingDetectorOptions& ceiling,
                              const InnerLineCheckOptions& options, CorridorGeometry* geometry,
                              ImageEdges* edges = nullptr);

}  // namespace corridor
