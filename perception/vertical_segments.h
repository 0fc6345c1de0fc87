#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace corridor {

// Straight edges that run within max_tilt_deg of the image's columns (door frames, wall corners,
// pillars as a level or pitched camera sees them), found in one pass over the image: on every
// row_step-th row, the peaks of the horizontal gradient, linked from row to row into chains, each
// chain fitted by x = a + b y. The peaks are placed to a fraction of a pixel, so a segment's tilt
// is good to a small fraction of a degree: what a roll estimate needs, at a few per cent of the
// cost of a Hough transform of the whole image.
struct VerticalSegmentOptions {
  int row_step = 2;           // Rows scanned: every row_step-th one.
  double min_gradient = 60;   // Least |Sobel x| (3x3, grey levels) of a peak.
  double min_length_px = 30;  // Shortest segment, rows.
  double max_tilt_deg = 40;   // Largest angle to the image's columns.
  double max_rms_px = 0.7;    // Largest RMS distance of a chain's peaks from its line.

  bool Check(std::string* why) const;
};

// Segments (x0, y0, x1, y1), top end first, in `grey`'s pixels (8-bit, 1 to 4 channels; of a
// BGR(A) image, the green channel is used). When `skip` is not empty (one entry per row), the
// columns [skip[y][0], skip[y][1]) of row y are not scanned: a region known to hold no such edges
// (the floor between the walls).
std::vector<cv::Vec4d> FindVerticalSegments(const cv::Mat& grey,
                                            const VerticalSegmentOptions& options,
                                            const std::vector<cv::Vec2i>& skip = {});
// The same into *segments, which keeps its memory.
void FindVerticalSegments(const cv::Mat& grey, const VerticalSegmentOptions& options,
                          const std::vector<cv::Vec2i>& skip, std::vector<cv::Vec4d>* segments);

}  // namespace corridor
