#pragma once

#include <opencv2/core.hpp>

#include "core/camera.h"

namespace corridor {

// An image searched at a lower resolution, with the camera that matches it.
struct WorkingImage {
  cv::Mat bgr;     // The image halved (cv::pyrDown) until it fits; the input's own pixels if not.
  Camera camera;   // The input camera scaled to bgr: f halved, principal point moved to match.
  int scale = 1;   // Input pixels per working pixel: 2 to the number of halvings.
};

// How many input pixels one working pixel spans when an image `width` wide is halved until it is
// at most max_width wide (0: never): 1, 2, 4, ... (cv::pyrDown rounds odd sizes up).
int WorkingScale(int width, int max_width);

// Halves the image (cv::pyrDown) until it is at most max_width wide (0: never), and scales the
// camera to match: cv::pyrDown's kernel is centred on every second pixel, so pixel i of a halved
// image lies at input pixel 2 i, and f, cx and cy all halve. Distortion coefficients act on
// normalised coordinates and carry over unchanged.
WorkingImage HalveToWidth(const cv::Mat& bgr, const Camera& camera, int max_width);

}  // namespace corridor
