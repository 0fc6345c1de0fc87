#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace corridor {

struct OrientedHoughOptions {
  int threshold = 25;              // Votes a line needs before it is followed.
  double min_length = 10;          // Shortest segment kept, px (along u or v, as cv::HoughLinesP).
  double max_gap = 6;              // Largest gap bridged inside one segment, px.
  double angle_window_deg = 15.0;  // Each edge pixel votes only for line normals this close to its gradient's direction.
};

// The progressive probabilistic Hough transform of Matas, Galambos and Kittler (2000), as
// cv::HoughLinesP runs it (1 px, 1 degree; edge pixels drawn in random order; a line whose
// bin reaches the threshold is followed along the edge map in both directions, bridging gaps up
// to max_gap, and its pixels are removed), except that each edge pixel votes only for the line
// normals within angle_window_deg of its own gradient direction instead of for all 180: about a
// tenth of the votes, and pixels of other lines and of texture no longer pile onto a line's bin.
// One more difference from OpenCV's loop: a pixel that was never drawn is not un-voted when the
// line through it is removed (OpenCV un-votes it, which can leave negative bins). And the order
// is fixed by each pixel's coordinates (a hash), not by a random number generator drawing from the
// pool: one edge pixel more or less changes the segments around it only, not the whole set.
// `edges`: CV_8U edge map (non-zero = edge); `dx`, `dy`: CV_16S gradients of the same size (the
// Canny input). Segments are (u0, v0, u1, v1) in the edge map's pixels.
void OrientedHoughSegments(const cv::Mat& edges, const cv::Mat& dx, const cv::Mat& dy,
                           const OrientedHoughOptions& options, std::vector<cv::Vec4i>* segments);

}  // namespace corridor
