#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/status.h"

namespace corridor {

// Blurs rows [from, to) of an 8-bit image of 1 to 4 channels with a binomial kernel along its
// columns and rows: `taps` 3 gives [1 2 1] / 4 (a Gaussian of sigma 0.71), 5 gives
// [1 4 6 4 1] / 16 (sigma 1.0), in integers, rounded half up. Rows just outside [from, to) are
// read where the image has them, as cv::GaussianBlur reads around a view; the image's own
// borders are reflected (BORDER_REFLECT_101). `out` gets to - from rows. Integer taps (AVX2 where
// the CPU has it) make it cheaper than cv::GaussianBlur, which takes a 7-tap float kernel on a
// view for sigma 1 (docs/results.md, "Image kernels").
// InvalidArgument for another depth or channel count, taps other than 3 and 5, or an empty or
// out-of-range row range.
Status BinomialBlur(const cv::Mat& image, int from, int to, int taps, cv::Mat* out);

// Gaussian blur of a view of an 8-bit image as OpenCV blurs a whole one, bit for bit: the rows of
// cv::GaussianBlur(whole image, sigma) (its fixed-point kernel in 1/256, rounded once), the rows
// around the view read where its matrix has them. For 1 to 4 channels, views that span their
// matrix's columns and a sigma whose kernel has at most five taps (up to about 0.9), in integers
// with AVX2; otherwise cv::GaussianBlur(view, sigma) itself. (On a band of rows OpenCV takes
// another, floating-point path, one grey level off at one pixel in six or so.) Sigma 0.8 over
// 640x248 colour pixels takes about a third of cv::GaussianBlur's time.
void GaussianBlurView(const cv::Mat& view, double sigma, cv::Mat* out);

}  // namespace corridor
