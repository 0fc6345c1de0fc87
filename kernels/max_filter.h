#pragma once

// The largest value over a square window (a grey-level dilation), without OpenCV's filter engine.

#include <opencv2/core.hpp>

namespace corridor {

// out(r, c) = the largest pixel of `image` (CV_8UC1) over rows r - reach .. r + reach and columns
// c - reach .. c + reach that lie inside the image: what cv::dilate gives with a
// (2 reach + 1)-square kernel of ones and its default border. `out` gets a new matrix when it
// shares the image's pixels; it keeps its buffer from call to call otherwise. reach >= 0.
void MaxFilterSquare(const cv::Mat& image, int reach, cv::Mat* out);

}  // namespace corridor
