#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/recover_depth.h"

namespace corridor {

// Depth (CV_32F metres) as a colour image: turbo colour map from 0 to max_depth, black where 0.
cv::Mat ColorizeDepth(const cv::Mat& depth, double max_depth);

// A vertical colour bar for ColorizeDepth's scale, labelled in metres, `height` pixels tall.
cv::Mat DepthColorBar(int height, double max_depth);

// The image with the Hough segments (grey), the left (green) and right (magenta) junction lines
// extended to the vanishing point, and their support points.
cv::Mat DrawJunctions(const cv::Mat& bgr, const JunctionPair& junctions);

// The picture a person looks at: the input with the lines beside the coloured depth and its
// colour bar, with a caption (status, geometry, time). Where the geometry is not the detected
// lines' alone (result.fallback: a wall moved, a width held, one junction and a known width), the
// geometry's own floor/wall junctions are drawn too (thin white) and the note is a caption line.
cv::Mat MakeResultPanel(const cv::Mat& bgr, const RecoverDepthResult& result, double max_depth);

// Places images side by side (same height after scaling), with `gap` black pixels between.
cv::Mat HorizontalConcat(const std::vector<cv::Mat>& images, int gap = 4);

}  // namespace corridor
