#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"

namespace corridor {

// An image searched at a lower resolution, with the camera that matches it.
struct WorkingImage {
  cv::Mat bgr;    // The image halved (PyrDown) until it fits; the input's own pixels if not.
  Camera camera;  // The input camera scaled to bgr: f halved, principal point moved to match.
  int scale = 1;  // Input pixels per working pixel: 2 to the number of halvings.
};

// cv::pyrDown(image, *halved) with the default size and border: the same pixels, computed about
// twice as fast with AVX2 for 8-bit images of 1 to 4 channels at least 3 px on a side (every
// other image, or a CPU without AVX2, goes to cv::pyrDown itself).
// `blurred`, when given: the image's first rows blurred with [1 4 6 4 1] / 16 both ways at every
// pixel (BinomialBlur(image, 0, rows, 5), which another search of the frame has computed): the
// halved rows that fall on them are every second pixel of theirs, the same pixels, not summed
// again. Ignored unless it has the image's type and width and at most its rows.
void PyrDown(const cv::Mat& image, cv::Mat* halved, const cv::Mat* blurred = nullptr);

// How many input pixels one working pixel spans when an image `width` wide is halved until it is
// at most max_width wide (0: never): 1, 2, 4, ... (cv::pyrDown rounds odd sizes up).
int WorkingScale(int width, int max_width);

// Halves the image (PyrDown) until it is at most max_width wide (0: never), and scales the
// camera to match: cv::pyrDown's kernel is centred on every second pixel, so pixel i of a halved
// image lies at input pixel 2 i, and f, cx and cy all halve. Distortion coefficients act on
// normalised coordinates and carry over unchanged.
// `blurred`: as PyrDown's, for the first halving.
WorkingImage HalveToWidth(const cv::Mat& bgr, const Camera& camera, int max_width,
                          const cv::Mat* blurred = nullptr);
// The same into *out, whose matrix keeps its memory for the first halving when nothing else
// holds it.
void HalveToWidth(const cv::Mat& bgr, const Camera& camera, int max_width, const cv::Mat* blurred,
                  WorkingImage* out);

}  // namespace corridor
