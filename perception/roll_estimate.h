#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"

namespace corridor {

// The roll of a camera about its optical axis, which the corridor model leaves out, from the
// walls' vertical edges (door frames, corners, pillars): in the world they meet at the vertical
// vanishing point, which lies straight below (above) the principal point for a camera without
// roll and is turned about it by the roll.
struct RollEstimateOptions {
  double max_roll_deg = 6;         // Rolls searched, either way, degrees.
  double step_deg = 0.05;          // The search's step, degrees.
  double inlier_deg = 2;           // A segment within this of the rolled vertical vanishing point agrees with it.
  double candidate_deg = 10;       // Segments within this of the unrolled one take part.
  double corridor_deg = 4;         // ... unless they run within this of the corridor's vanishing point.
  double min_length_px = 30;       // Shortest segment, px.
  int min_segments = 5;            // Least agreeing segments...
  int min_each_side = 2;           // ... and this many on each side of the corridor's vanishing point,
  double min_spread = 0.015;       // ... or, on one wall, spread enough to fix the vertical vanishing point alone (see below).
  double max_cost_fraction = 0.3;  // The roll's cost at most this fraction of the cost with no roll.
  double min_roll_deg = 0.5;       // Smaller rolls are left in: the corridor model takes them with no measurable loss.

  bool Check(std::string* why) const;
};

struct RollEstimate {
  bool found = false;  // True when the evidence passed every test.
  double roll = 0;     // Radians, > 0: the image turned clockwise (its right side lower); 0 unless found.
  int segments = 0;    // Segments that agree with the roll found.
};

// The roll of the camera that took `bgr` (8-bit BGR, `camera`'s size), given the corridor's yaw
// and pitch estimated without it (`geometry`, whose width, offset and camera height mark the
// floor, whose edges take no part). The segments are FindVerticalSegments' on the grey image,
// placed to a fraction of a pixel. A search over the roll at the fit's
// pitch (length-weighted angles to the rolled vertical vanishing point, each capped at
// inlier_deg) picks the agreeing segments and gates the evidence; the roll is that of the
// vertical vanishing point fitted freely to them, so that the fit's pitch error is not taken for
// a roll. Segments on both walls fix that point; segments on one wall only fix it when their
// planes through the camera centre spread in both directions about it: the second eigenvalue of
// their length-weighted scatter at least min_spread of the largest (door frames at several
// depths, not one door's two jambs).
RollEstimate EstimateRoll(const cv::Mat& bgr, const Camera& camera,
                          const CorridorGeometry& geometry, const RollEstimateOptions& options);

// The map from `camera`'s pixels to those of the same camera turned by `roll` about its optical
// axis (2x3, for cv::warpAffine): a rolled frame turned by -roll is level.
cv::Mat RollTurn(const Camera& camera, double roll);

}  // namespace corridor
