#pragma once

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace corridor {

// A straight line found in the image: several collinear Hough segments merged (the paper's NMS)
// into one, in full-image pixel coordinates.
struct MergedLine {
  Eigen::Vector3d line;        // a u + b v + c = 0, a^2 + b^2 = 1, with b >= 0 (normal points down).
  Eigen::Vector2d start;       // Extent of its segments along the line: the end with smaller u.
  Eigen::Vector2d end;         // The end with larger u.
  double length = 0;           // Extent, px.
  double covered = 0;          // Summed length of its segments, px (<= length when broken).
  double slope = 0;            // dv/du (< 0 rises to the right: a left junction).
  double inclination_deg = 0;  // Angle from the horizontal, in [0, 90].
};

// Fills m's start, end, length, slope and inclination from `points` projected onto m->line (which
// must be set, with b >= 0).
void SetExtentAlongLine(const std::vector<Eigen::Vector2d>& points, MergedLine* m);
// The same from `count` points at `points` (no vector needed).
void SetExtentAlongLine(const Eigen::Vector2d* points, size_t count, MergedLine* m);

// Canny edges (in the ROI rows [roi_top, rows)) and their Hough segments in full-image coordinates.
struct EdgeSegments {
  cv::Mat edges;                    // CV_8U edge map of the ROI (255 = edge).
  int roi_top = 0;                  // First image row of the ROI.
  double canny_high = 0;            // The Canny high threshold used.
  std::vector<cv::Vec4f> segments;  // (u0, v0, u1, v1) in full-image coordinates.
  cv::Mat dx, dy;                   // CV_16S colour gradient of the (blurred) ROI: Canny's input.
};

struct SegmentOptions {
  double blur_sigma;              // Gaussian blur before Canny, px.
  double canny_high;              // Canny high threshold on |dx| + |dy|; 0 = automatic.
  double canny_low_ratio;         // Low threshold = ratio * high.
  double auto_percentile;         // Automatic high threshold: this percentile of the gradients...
  double auto_min;                // ... but at least this.
  int hough_threshold;            // Hough votes.
  double hough_min_length;        // Shortest segment, px.
  double hough_max_gap;           // Largest gap, px.
  double hough_angle_window_deg;  // > 0: OrientedHoughSegments, each edge pixel voting within this of its gradient's direction; 0: cv::HoughLinesP.
};

// Canny (on colour gradients for a BGR image) + probabilistic Hough on the rows [roi_top, rows).
EdgeSegments DetectSegments(const cv::Mat& image, int roi_top, const SegmentOptions& options);
// The same into *out, whose segment vector keeps its memory, and so do its matrices when nothing
// else holds them.
void DetectSegments(const cv::Mat& image, int roi_top, const SegmentOptions& options,
                    EdgeSegments* out);

// The Hough step of DetectSegments alone, on `found`'s edges and gradients with the Hough settings
// of `options` (threshold, shortest segment, gap, angle window): segments in the coordinates of
// found.segments. A second look at the same edges with other settings costs no edge detection.
std::vector<cv::Vec4f> HoughSegments(const EdgeSegments& found, const SegmentOptions& options);
// The same into *segments, which keeps its memory.
void HoughSegments(const EdgeSegments& found, const SegmentOptions& options,
                   std::vector<cv::Vec4f>* segments);

// Groups segments whose lines agree within the tolerances and fits one line per group
// (length-weighted total least squares of their endpoints).
std::vector<MergedLine> MergeSegments(const std::vector<cv::Vec4f>& segments, double angle_deg,
                                      double distance_px);
// The same into *merged (replaced; its memory kept).
void MergeSegments(const std::vector<cv::Vec4f>& segments, double angle_deg, double distance_px,
                   std::vector<MergedLine>* merged);

// A MergedLine through two points (normalised, normal pointing down, extent from the points).
MergedLine LineThrough(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// The end of a line's extent nearer the image bottom.
Eigen::Vector2d LowEnd(const MergedLine& line);

}  // namespace corridor
