#pragma once

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "corridor_depth/status.h"

namespace corridor {

// One floor/wall junction line in raw image pixels.
struct JunctionLine {
  Eigen::Vector3d line = Eigen::Vector3d::Zero();      // a u + b v + c = 0 with a^2 + b^2 = 1.
  Eigen::Vector2d near_end = Eigen::Vector2d::Zero();  // Support extent: the end nearest the camera (lowest in the image).
  Eigen::Vector2d far_end = Eigen::Vector2d::Zero();   // Support extent: the end toward the vanishing point.
  std::vector<Eigen::Vector2d> support;                // Edge pixels that support the line.
  double support_length = 0.0;                         // Pixels of the line covered by support.
  double confidence = 0.0;                             // In [0, 1]: how sure the detector is.
  std::vector<Eigen::Vector2d> edge_points;            // Sub-pixel edge points measured on the image (raw pixels), when the solvers are to see them (RecoverDepthOptions::solver_evidence); else empty.
  std::vector<double> edge_weights;                    // One weight per edge point (mean 1).
};

// Both junctions, or the reason they were not found.
struct JunctionPair {
  Status status;                                              // kNoCorridorFound with a reason when no pair was found.
  JunctionLine left;                                          // The left floor/wall junction (valid when status.ok()).
  JunctionLine right;                                         // The right floor/wall junction.
  Eigen::Vector2d vanishing_point = Eigen::Vector2d::Zero();  // Intersection of the two lines.
  double floor_texture = -1;                                  // Fraction of the floor between the lines in strong edges along no corridor line (JunctionDetectorOptions::max_floor_texture); -1 = not measured.
  std::vector<cv::Vec4f> segments;                            // All Hough segments in the ROI (for drawing and debugging).
  bool relaxed_hough = false;                                 // True when the pair came from the second, relaxed Hough look (JunctionDetectorOptions::relaxed_hough_threshold): a faint or broken junction.

  // Per side, a parallel line just below the chosen junction that looks less like the floor's
  // boundary: the junction if the chosen line is a baseboard's top after all (another cue, the
  // ceiling, decides; see RecoverDepthOptions::ceiling_checks_baseboards).
  bool has_left_lower = false, has_right_lower = false;
  // Per side (left, right): the junction stands at the middle of a baseboard-and-reflection band
  // (a polished floor): its own edge is faint, and the band's top above it is the baseboard's.
  bool at_reflected_band[2] = {false, false};
  JunctionLine left_lower, right_lower;

  // When only one side has candidates (the other junction hidden or out of view): its best line,
  // for a fallback with a known width. Never a made-up second line.
  bool has_single = false;                              // True when `single` holds the one visible junction.
  bool single_is_left = false;                          // Which side it is.
  JunctionLine single;                                  // The line (raw pixels).
  bool single_has_vp = false;                           // True when other lines meet it at a vanishing point...
  Eigen::Vector2d single_vp = Eigen::Vector2d::Zero();  // ... here (on the line).
  int single_vp_votes = 0;                              // How many lines voted for it.
};

// N points evenly spaced along the line between near_end and far_end (inclusive).
std::vector<Eigen::Vector2d> SampleAlongLine(const JunctionLine& line, int n);
// The same into *points, which keeps its memory.
void SampleAlongLine(const JunctionLine& line, int n, std::vector<Eigen::Vector2d>* points);

}  // namespace corridor
