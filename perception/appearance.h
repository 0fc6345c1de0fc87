#pragma once

#include <opencv2/core.hpp>

#include "perception/line_segments.h"

namespace corridor {

// The floor's appearance: a reference colour sampled where almost every corridor photo shows
// floor (the bottom centre of the image), in 8-bit CIE Lab (OpenCV's scaling).
struct FloorAppearance {
  cv::Vec3f lab;      // Median Lab colour of the reference patch.
  float spread = 1;   // Median distance of the patch's pixels to it (texture), >= 1.
};

// Distance of two 8-bit Lab colours (OpenCV's scaling) with lightness weighted a quarter: shading,
// light falloff and grazing angles change lightness along a uniform surface.
float LabDistance(const cv::Vec3f& a, const cv::Vec3f& b);

// `lab`: the ROI rows [roi_top, image rows) of the image in 8-bit Lab (CV_8UC3).
FloorAppearance SampleFloor(const cv::Mat& lab, int roi_top);

// How much a line looks like the floor's upper boundary, in [0, 1]: the floor-likeness of the
// strip just below it times the unlikeness of the strip above. Near 1 for the junction; near 0
// for lines inside the floor (grout, reflections: floor on both sides) and on the wall (baseboard
// tops, door bottoms: no floor below). `lab` as for SampleFloor.
double BoundaryScore(const cv::Mat& lab, const FloorAppearance& floor, const MergedLine& line,
                     int roi_top);

}  // namespace corridor
