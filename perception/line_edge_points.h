#pragma once

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace corridor {

// A point near a line where the colour gradient across the line peaks.
struct EdgePeak {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // Where, px (to a tenth of a pixel across the line).
  int major = 0;                                    // The row (column, for a line flatter than 45 degrees) it was sought on.
  double offset = 0;                                // Its signed distance from the line along that row (column), px.
  double strength = 0;                              // The gradient across the line there.
};

// How EdgePeaksAlong looks for the peaks.
struct EdgePeakSearch {
  double reach_px = 4;       // Peaks are sought this far from the line along each row (column), px, either side.
  double threshold = 40;     // Least colour gradient across the line (Sobel 3x3, the strongest channel) of a peak.
  int step_px = 1;           // Peaks are sought on every this many rows (columns).
  bool nearest_only = true;  // Keep only the peak nearest the line on each row (column); else all of them.
};

// True when a line (a, b, c) with a^2 + b^2 = 1 is crossed row by row (steeper than 45 degrees),
// false when column by column.
inline bool CrossedByRows(const Eigen::Vector3d& line) {
  return std::abs(line.x()) >= std::abs(line.y());
}

// The peaks of the colour gradient across `line` (a, b, c, a^2 + b^2 = 1) in `bgr` (8-bit,
// 3 channels): on every step_px-th row (column, for lines flatter than 45 degrees) between the
// positions t0 <= t1 along the line's direction (b, -a) from its point nearest the origin, the
// local maxima above the threshold within reach of where the line crosses it, the gradient being
// |n . (dx, dy)| of the 3x3 Sobel, the strongest of the three channels. Each peak is placed to a
// tenth of a pixel by a parabola through it and its neighbours. Rows (columns) whose search run
// leaves the image are skipped. Appended to *peaks in row (column) order. Returns the number of
// rows (columns) searched.
int EdgePeaksAlong(const cv::Mat& bgr, const Eigen::Vector3d& line, double t0, double t1,
                   const EdgePeakSearch& search, std::vector<EdgePeak>* peaks);

// The position along `line`'s direction (b, -a) of the point p, from the line's point nearest the
// origin (EdgePeaksAlong's t).
inline double PositionAlong(const Eigen::Vector3d& line, const Eigen::Vector2d& p) {
  return p.dot(Eigen::Vector2d(line.y(), -line.x()));
}

}  // namespace corridor
