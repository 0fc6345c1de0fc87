#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace corridor {

// Bins of the gradient histogram: |dx| + |dy| of a 3x3 Sobel on 8 bits is at most 2040.
constexpr int kGradientBins = 2048;

// Colour gradients: per pixel, the 3x3 Sobel derivatives (CV_16S, reflect-101 borders, the image
// taken on its own, as cv::Sobel does on a whole image) of the channel whose |dx| + |dy| is the
// largest (the first channel on ties), so that a boundary between two colours of equal brightness
// (a dark baseboard on a dark floor) still gives edges. A grey image gives its own derivatives
// (through cv::Sobel, so a view uses the pixels around it). When `histogram` is not null it
// receives kGradientBins counts of min(|dx| + |dy|, bins - 1). Multi-channel 8-bit images take
// one fused pass; other depths go through cv::Sobel per channel, with the same result.
// With `histogram_floor` F > 0 the values below F may all be counted in bin F - 1 (the bins below
// it then hold 0): HistogramPercentile still gives every percentile that is at least F, and F - 1
// for the others; counting the many small values together is cheaper.
void ColorGradient(const cv::Mat& image, cv::Mat* dx, cv::Mat* dy, std::vector<int>* histogram,
                   int histogram_floor = 0);

// The p-th percentile (0..100) of a gradient histogram of `total` pixels: the first bin at which
// the running count reaches p% of them.
double HistogramPercentile(const std::vector<int>& histogram, double total, double p);

}  // namespace corridor
