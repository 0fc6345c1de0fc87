#pragma once

#include <array>
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
// The same disagreement comes from the other wall put too far, by a baseboard's top taken for its
// junction (its wall distance and ceiling scaled up by h / (h - baseboard height)). The two are
// told apart by the band each move would cross: moving the near wall out crosses floor (a line
// inside the floor to the junction), moving the far wall in crosses the baseboard (its top to the
// junction below it). When both bands look unlike the floor, the far wall is moved in instead.
struct InnerLineCheckOptions {
  double min_disagreement = 0.15;            // Least relative difference of the two sides' ceiling heights that moves a wall.
  double min_support = 0.35;                 // Least fraction of each side's ceiling junction on edges (the ceiling search's own minimum), counted over at least half its samples.
  double strong_support = 0.45;              // When the trusted side reaches min_support only on its samples in view (a narrow vertical view shows its junction from a few metres on), the side to move needs this much, of at least half its samples.
  double min_above_camera = 0.2;             // The wide search: ceilings from this far above the camera, m, up to the ceiling search's max_height.
  double max_line_support = 0.8;             // A floor junction on edges of its orientation over this fraction of its samples in view (sampled as the ceiling search samples its lines) is not moved: a box's edge or floor line covers less.
  double min_band_contrast = 1.45;           // Both bands (see above) at least this unlike the floor below them (BandContrast, in floor spreads): a baseboard's top was taken on the far side, which moves in; 0 = never.
  double min_baseboard_disagreement = 0.08;  // Least relative difference of the two sides' ceiling heights that moves the far wall in (a baseboard's top is a few per cent of the camera height above the floor).

  bool Check(std::string* why) const;
};

struct InnerLineCheck {
  bool moved = false;                  // True when a wall was moved (geometry updated).
  int side = -1;                       // The wall moved: 0 left, 1 right.
  double factor = 1;                   // Its distance was multiplied by this (> 1 out, < 1 in).
  bool baseboard = false;              // True when the far wall was moved in (a baseboard's top taken for its junction).
  double band_contrast[2] = {-1, -1};  // Per side, the band the move would cross, unlike the floor by (BandContrast; -1 = not measured).
  double side_height[2] = {0, 0};      // The wide search's ceiling height per side, m (0 = none).
  double side_support[2] = {0, 0};     // Their supports.
  double line_support = 0;             // The floor junction to move: its support (0 when not measured).
};

// Runs the check on the search image (`bgr` with `camera`, as the ceiling search sees them);
// `ceiling` are the ceiling search's options (its min_height..max_height bound the ceiling the
// trusted side may give). Updates *geometry (width and offset) when a wall moves. `edges`: the
// frame's edges of the search image (see DetectCeiling), or null. `has_lower` (left, right): the
// sides whose junction has a lower parallel line beside it (JunctionPair::has_left_lower): a
// baseboard's top may have been taken for it, its wall then too far and its ceiling too high.
// Where the trusted side reaches min_support only on its samples in view
// (InnerLineCheckOptions::strong_support), such a side is not trusted.
// The least disagreement (relative) of the two ceiling sides at which CheckInnerLine may move a
// wall.
double MinInnerLineDisagreement(const InnerLineCheckOptions& options);

// What the check did, for a frame's note ("left wall moved out 1.18x: ..."); empty when nothing
// moved.
std::string DescribeInnerLineCheck(const InnerLineCheck& check);

InnerLineCheck CheckInnerLine(const cv::Mat& bgr, const Camera& camera,
                              const CeilingDetectorOptions& ceiling,
                              const InnerLineCheckOptions& options, CorridorGeometry* geometry,
                              ImageEdges* edges = nullptr,
                              std::array<bool, 2> has_lower = {false, false});

}  // namespace corridor
