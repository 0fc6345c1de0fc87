#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <opencv2/core.hpp>

#include "core/status.h"
#include "perception/junction_lines.h"
#include "perception/line_segments.h"

namespace corridor {

// Options of the junction-line detector (paper III-A). Defaults are the paper's where it gives
// one, and work on generated and real corridors.
struct JunctionDetectorOptions {
  double roi_top_fraction = 0.5;                    // The search region starts at this fraction of the height (paper: the middle).
  double blur_sigma = 0.8;                          // Gaussian blur before Canny, px (0 = none).
  double canny_high = 0;                            // Canny high threshold on |dx|+|dy| (Sobel 3x3); 0 = automatic.
  double canny_low_ratio = 0.4;                     // Canny low threshold as a fraction of the high one.
  double canny_auto_percentile = 90;                // Automatic high threshold: this percentile of the ROI's gradients...
  double canny_auto_min = 40;                       // ... but at least this, so that flat images give no edges.
  int hough_threshold = 25;                         // Probabilistic Hough accumulator threshold (votes).
  double hough_min_length_fraction = 0.04;          // Shortest Hough segment, as a fraction of the image height.
  double hough_max_gap = 6;                         // Largest gap bridged inside one Hough segment, px.
  double hough_angle_window_deg = 15;               // Each edge pixel votes only for lines within this of its gradient's direction (OrientedHoughSegments); 0 = cv::HoughLinesP, all angles.
  int relaxed_hough_threshold = 12;                 // When no pair is found, Hough looks again at the same edges with this threshold (votes): a faint junction broken by door bottoms gives only short pieces; 0 = no second look.
  double relaxed_hough_min_length_fraction = 0.02;  // ... and this shortest segment, fraction of the height.
  double relaxed_min_line_fraction = 0.2;           // A line found only on the second look is at least this long, fraction of the height (a broken junction spans much of the image; chance alignments are short).
  double relaxed_min_partner_boundary = 0.1;        // ... and pairs only with a first-look line whose BoundaryScore (floor below, something else above) is at least this.
  double merge_angle_deg = 2.5;                     // Segments whose angles differ less than this may merge (the paper's NMS).
  double merge_distance_px = 4;                     // ... and whose lines pass within this distance of each other.
  double min_length_fraction = 0.1;                 // Scene prior (eq. 2): shortest junction, fraction of the height H (paper: 0.25).
  double max_length_fraction = 0.75;                // Scene prior (eq. 2): longest junction, fraction of the diagonal (paper 1/2); 0 = no limit.
  double min_inclination_deg = 8;                   // Scene prior: flattest junction, degrees from horizontal (cross-corridor edges are flatter).
  double max_inclination_deg = 80;                  // Scene prior: steepest junction, degrees from horizontal (the paper: 90 - atan(H/W), set -1).
  double baseboard_band_contrast = 1.45;            // A lower line parallel to the chosen one is the junction (the chosen one a baseboard top) when the band between them is this unlike the floor below, in floor spreads (BandContrast); raise it for glossy floors that mirror the baseboard; 0 = off.
  double support_distance_px = 2.0;                 // Edge pixels this close to a chosen line support its refit.
  double max_edge_density = 0.2;                    // More edge pixels than this fraction of the ROI: noise or texture, not a corridor.
  double max_floor_texture = 0.015;                 // More of the floor between the chosen junctions in strong edges along no corridor line than this fraction: not a corridor (an outdoor scene, a still life); 0 = no check.
  int strong_edge_gradient = 240;                   // A strong edge: colour |dx| + |dy| (Sobel 3x3) at least this, a step of about 60 grey levels.
  double floor_line_tolerance_deg = 15;             // Floor edges within this of horizontal, vertical or the vanishing point are corridor lines (joints, tape, reflections).
  int max_work_width = 640;                         // Wider images are halved (pyrDown) until they fit before edges and lines are found; 0 = full resolution.
  bool refit_full_resolution = true;                // After a search on a halved image, each chosen junction is refitted on the full-resolution gradient (RefitJunctionAtFullResolution).

  bool Check(std::string* why) const;
};

// The edge and Hough options of the junction search for an image `height` rows tall searched at
// 1/scale of its resolution (the shortest segment scales with the working height).
SegmentOptions JunctionSegmentOptions(const JunctionDetectorOptions& options, int height,
                                      int scale);

// Finds the left and right floor/wall junctions. InvalidArgument for an empty or non-8-bit
// image; otherwise OK, with result->status = kNoCorridorFound and a reason when no plausible
// pair exists (tiny, blank or noise images, scenes that are not corridors).
Status DetectJunctions(const cv::Mat& bgr, const JunctionDetectorOptions& options,
                       JunctionPair* result);

// The same, given `halved`: the whole of `bgr` (8-bit, 3 channels) halved by cv::pyrDown as many
// times as options.max_work_width asks, by a caller that needs that image too (the ceiling and
// end-wall searches). The result is the other overload's: it halves only the search region, whose
// rows come out the same. InvalidArgument when `halved` is not that image's size or type.
Status DetectJunctions(const cv::Mat& bgr, const cv::Mat& halved,
                       const JunctionDetectorOptions& options, JunctionPair* result);

// The points of `edges` on a junction's floor side of the vanishing point `vp` (`left`: the left
// junction's, left of vp; else right of it; and not above it), in order: a junction's support.
std::vector<Eigen::Vector2d> FloorSidePixels(const std::vector<Eigen::Vector2d>& edges,
                                             const Eigen::Vector2d& vp, bool left);

}  // namespace corridor
