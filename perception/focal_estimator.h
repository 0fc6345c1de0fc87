#pragma once

#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "corridor_depth/status.h"

namespace corridor {

// Options of the focal-length estimator (`--focal=auto`): line segments over the whole image,
// the corridor's vanishing point, then the vanishing points orthogonal to it.
struct FocalEstimatorOptions {
  double blur_sigma = 0.8;                  // Gaussian blur before Canny, px (0 = none).
  double canny_low_ratio = 0.4;             // Canny low threshold as a fraction of the high one.
  double canny_auto_percentile = 90;        // Automatic Canny high threshold: this percentile of the gradients...
  double canny_auto_min = 40;               // ... but at least this, so that flat images give no edges.
  int hough_threshold = 20;                 // Probabilistic Hough accumulator threshold (votes).
  double hough_min_length_fraction = 0.03;  // Shortest Hough segment, as a fraction of the image diagonal.
  double hough_max_gap = 3;                 // Largest gap bridged inside one Hough segment, px.
  double merge_angle_deg = 1.0;             // Segments whose angles differ less than this may merge...
  double merge_distance_px = 1.5;           // ... and whose lines pass within this distance of each other.
  double min_line_length_fraction = 0.04;   // Merged lines shorter than this fraction of the diagonal are ignored.
  double refit_distance_px = 2.0;           // Sub-pixel refit: gradient peaks this close to a merged line refit it (0 = no refit).
  double inlier_distance_px = 1.5;          // A line meets a vanishing point when its endpoints lie this close to the line from its midpoint to it.
  double robust_scale_px = 0.3;             // Scale of the Cauchy loss of the final refinement, px.
  bool assume_zero_roll = true;             // The camera has no roll (as the geometry solvers assume): fit focal, pitch and yaw only.
  int ransac_pairs = 3000;                  // Line pairs tried per vanishing point (all pairs when there are fewer).
  unsigned seed = 7;                        // Seed of the pair sampling, so that every run is the same.
  double max_corridor_vp_distance = 1.0;    // The corridor's vanishing point lies within this many image diagonals of the centre.
  int min_corridor_support = 4;             // Fewest lines through the corridor's vanishing point.
  int min_second_support = 3;               // Fewest lines through an orthogonal vanishing point for it to count.
  double min_hfov_deg = 20;                 // Plausible focal lengths: narrowest horizontal field of view, degrees...
  double max_hfov_deg = 150;                // ... and widest, degrees.
  double max_second_vp_distance = 15;       // The nearest orthogonal vanishing point lies within this many focal lengths of the centre (farther: f is ill-conditioned).

  // True when every field is usable; otherwise fills *why with what is wrong.
  bool Check(std::string* why) const;
};

// What EstimateFocal found. Vanishing points are in pixels; the principal point is the centre.
struct FocalEstimate {
  double focal_px = 0;                 // fx = fy, pixels.
  bool from_vanishing_points = false;  // False: `focal_px` is the fallback field of view's.
  std::string how;                     // E.g. "vanishing points (corridor + across + vertical)", or why it fell back.
  Eigen::Vector2d corridor_vp{0, 0};   // The corridor axis' vanishing point (when corridor_support > 0).
  Eigen::Vector2d second_vp{0, 0};     // The orthogonal vanishing point nearest the centre (when second_support > 0).
  std::string second_family;           // "across" or "vertical": the lines through second_vp.
  int corridor_support = 0;            // Lines through corridor_vp.
  int second_support = 0;              // Lines through second_vp.
  int third_support = 0;               // Lines through the third (orthogonal to both) vanishing point.
  double rms_px = 0;                   // RMS distance of the supporting lines' endpoints from their vanishing points' lines, px.
};

// Estimates the focal length (square pixels, principal point at the image centre) from the
// corridor's vanishing point and one or two orthogonal to it: f^2 = -(v1 - c).(v2 - c), refined
// over all supporting lines. When no usable orthogonal vanishing point exists, returns OK with
// the focal of `fallback_hfov_deg` (horizontal field of view, degrees), from_vanishing_points =
// false and `how` saying why. InvalidArgument for an empty, tiny or non-8-bit image, bad options,
// a fallback that is not a field of view in (0, 180), or a null estimate.
Status EstimateFocal(const cv::Mat& bgr_image, const FocalEstimatorOptions& options,
                     double fallback_hfov_deg, FocalEstimate* estimate);

}  // namespace corridor
