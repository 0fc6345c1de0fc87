#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <opencv2/core.hpp>

#include "corridor_depth/status.h"
#include "corridor_depth/junction_lines.h"
#include "perception/line_segments.h"
#include "corridor_depth/stage_options.h"

namespace corridor {

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
// The same into *side (its memory reused).
void FloorSidePixels(const std::vector<Eigen::Vector2d>& edges, const Eigen::Vector2d& vp,
                     bool left, std::vector<Eigen::Vector2d>* side);

}  // namespace corridor
