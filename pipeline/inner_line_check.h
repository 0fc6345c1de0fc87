#pragma once

#include <array>
#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "perception/ceiling_detector.h"
#include "corridor_depth/stage_options.h"

namespace corridor {

struct InnerLineCheck {
  bool moved = false;                  // True when a wall was moved (geometry updated).
  int side = -1;                       // The wall moved: 0 left, 1 right.
  double factor = 1;                   // Its distance was multiplied by this (> 1 out, < 1 in).
  bool baseboard = false;              // True when the far wall was moved in (a baseboard's top taken for its junction).
  bool far = false;                    // True when a wall whose ceiling shows only above any ceiling searched was moved in (CheckFarWall).
  double band_contrast[2] = {-1, -1};  // Per side, the band the move would cross, unlike the floor by (BandContrast; -1 = not measured).
  double side_height[2] = {0, 0};      // The wide search's ceiling height per side, m (0 = none).
  double side_support[2] = {0, 0};     // Their supports.
  double line_support = 0;             // The floor junction to move: its support (0 when not measured).
  double target_support = -1;          // The junction where the move puts it: its best support within 8% of the move (-1 when not measured).
};

// The least disagreement (relative) of the two ceiling sides at which CheckInnerLine may move a
// wall.
double MinInnerLineDisagreement(const InnerLineCheckOptions& options);

// What the check did, for a frame's note ("left wall moved out 1.18x: ..."); empty when nothing
// moved.
std::string DescribeInnerLineCheck(const InnerLineCheck& check);

// Runs the check on the search image (`bgr` with `camera`, as the ceiling search sees them);
// `ceiling` are the ceiling search's options (its min_height..max_height bound the ceiling the
// trusted side may give). Updates *geometry (width and offset) when a wall moves. `edges`: the
// frame's edges of the search image (see DetectCeiling), or null. `has_lower` (left, right): the
// sides whose junction has a lower parallel line beside it (JunctionPair::has_left_lower): a
// baseboard's top may have been taken for it, its wall then too far and its ceiling too high.
// Where the trusted side reaches min_support only on its samples in view
// (InnerLineCheckOptions::strong_support), such a side is not trusted. `at_reflected_band`
// (left, right): the sides whose junction stands at a baseboard-and-reflection band's middle
// (JunctionPair::at_reflected_band): not moved out, onto the baseboard's top.
InnerLineCheck CheckInnerLine(const cv::Mat& bgr, const Camera& camera,
                              const CeilingDetectorOptions& ceiling,
                              const InnerLineCheckOptions& options, CorridorGeometry* geometry,
                              ImageEdges* edges = nullptr,
                              std::array<bool, 2> has_lower = {false, false},
                              std::array<bool, 2> at_reflected_band = {false, false});

}  // namespace corridor
