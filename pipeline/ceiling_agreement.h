#pragma once

#include <cmath>

#include "perception/ceiling_detector.h"

namespace corridor {

// Two ceiling sides, each searched alone, whose heights above the camera are within this ratio
// agree: their walls need no check (the baseboard check), and confirm a narrower width (the hold).
inline constexpr double kCeilingSidesAgree = 1.06;

// Both ceiling junctions, each searched alone, with at least min_support: how far apart their
// heights above the camera are, |log(a_l / a_r)|; negative when they cannot be compared. A wrong
// wall distance scales its side's height.
inline double CeilingDisagreement(const CeilingEstimate& ceiling, double camera_height,
                                  double min_support = 0.45) {
  const double a_left = ceiling.side_height[0] - camera_height;
  const double a_right = ceiling.side_height[1] - camera_height;
  if (!ceiling.found || ceiling.side_support[0] < min_support ||
      ceiling.side_support[1] < min_support || !(a_left > 0.1) || !(a_right > 0.1)) {
    return -1;
  }
  return std::abs(std::log(a_left / a_right));
}

}  // namespace corridor
