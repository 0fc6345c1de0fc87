#pragma once

// Private to the junction detector: the search region at the working resolution, and the map
// from working pixels to image pixels.

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "corridor_depth/status.h"
#include "perception/floor_texture.h"

namespace corridor {

// The rows the junction search looks at, halved (cv::pyrDown's kernel is centred on every second
// pixel, so pixel i of an image halved to 1/scale lies at image pixel scale * i): working pixel
// (u, v) lies at image pixel (scale u, crop_top + scale v).
struct JunctionSearchRegion {
  int roi_top = 0;       // First image row of the search region.
  int scale = 1;         // Image pixels per working pixel: 1, 2, 4, ...
  int crop_top = 0;      // Image row of the working image's row 0, a multiple of scale.
  int work_roi_top = 0;  // The working row of the search region's top, roi_top / scale.
  cv::Mat work;          // The working image (8-bit colour).
};

// The search region of `color` (8-bit, 3 channels) from row roi_top, halved until the image fits
// max_work_width (0: never). Only the rows from crop_top are halved: roi_top less a few working
// rows for the kernel, rounded down to a multiple of the scale. `halved`, when not null, is the
// whole image already halved that many times (by a caller that needs it too): crop_top is 0 and
// the search region's rows are the same. InvalidArgument when `halved` is not that image's size
// or not 8-bit colour.
Status MakeJunctionSearchRegion(const cv::Mat& color, const cv::Mat* halved, int roi_top,
                                int max_work_width, JunctionSearchRegion* region);

// Segments (u0, v0, u1, v1) found in the working image into image pixels, in place.
void SegmentsToImage(const JunctionSearchRegion& region, std::vector<cv::Vec4f>* segments);

// Where the search region's edge map (and gradients), whose row 0 is the working row
// work_roi_top, lie in the image.
GradientGrid SearchRegionGrid(const JunctionSearchRegion& region);

// The nonzero pixels of the search region's edge map in image pixels, in row-major order.
std::vector<Eigen::Vector2d> EdgePixelsInImage(const JunctionSearchRegion& region,
                                               const cv::Mat& edges);
// The same into *points, which keeps its memory.
void EdgePixelsInImage(const JunctionSearchRegion& region, const cv::Mat& edges,
                       std::vector<Eigen::Vector2d>* points);

}  // namespace corridor
