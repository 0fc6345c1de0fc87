#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "perception/line_segments.h"

namespace corridor {

// The floor's appearance: a reference colour sampled where almost every corridor photo shows
// floor (the bottom centre of the image), in 8-bit CIE Lab (OpenCV's scaling).
struct FloorAppearance {
  cv::Vec3f lab;     // Median Lab colour of the reference patch.
  float spread = 1;  // Median distance of the patch's pixels to it (texture), >= 1.
};

// Distance of two 8-bit Lab colours (OpenCV's scaling) with lightness weighted a quarter: shading,
// light falloff and grazing angles change lightness along a uniform surface.
float LabDistance(const cv::Vec3f& a, const cv::Vec3f& b);

// 8-bit Lab colours of a few 8-bit BGR pixels, exactly as cv::cvtColor(COLOR_BGR2Lab) converts
// them inside a whole image (the conversion is per pixel), at the cost of these pixels only.
std::vector<cv::Vec3b> BgrToLab(const std::vector<cv::Vec3b>& bgr);

// `bgr`: the ROI rows [roi_top, image rows) of the 8-bit BGR image (CV_8UC3). Only the sampled
// pixels are converted to Lab: every `step`-th pixel of every `step`-th row (2 at up to 640 px
// wide; large images need no more samples than that).
FloorAppearance SampleFloor(const cv::Mat& bgr, int roi_top, int step = 2);

// The appearance of the strip 4 `scale` px below `line` (where BoundaryScore looks for floor), as
// SampleFloor gives it for the reference patch: the floor next to a junction that the reference
// patch does not show (a runner covers the bottom centre). `bgr` as for SampleFloor.
FloorAppearance SampleBelowLine(const cv::Mat& bgr, const MergedLine& line, int roi_top,
                                int scale = 1);

// How much a line looks like the floor's upper boundary, in [0, 1]: the floor-likeness of the
// strip just below it times the unlikeness of the strip above. Near 1 for the junction; near 0
// for lines inside the floor (grout, reflections: floor on both sides) and on the wall (baseboard
// tops, door bottoms: no floor below). `bgr` as for SampleFloor. The strips lie 4 `scale` px
// from the line, as 3x3 patches of pixels `scale` apart: `scale` is the junction search's
// working scale (1, or 2, 4... when large images are halved for it), so that the probes cover
// the same part of the scene at any resolution; a grout line's shadow, a few pixels wide in a
// 1280-pixel image, is not taken for the wall above it.
double BoundaryScore(const cv::Mat& bgr, const FloorAppearance& floor, const MergedLine& line,
                     int roi_top, int scale = 1);

// How much the strip 4 `scale` px above `line` looks like `floor`, in [0, 1]: the mean, over
// samples along the line, of the floor-likeness BoundaryScore gives a strip (1 for the floor's
// own colour). High above a stripe painted on the floor (the floor goes on beyond it); low above
// the junction. `bgr` and `scale` as for BoundaryScore; 0 when no sample is inside.
double FloorLikenessAbove(const cv::Mat& bgr, const FloorAppearance& floor,
                          const MergedLine& line, int roi_top, int scale = 1);

// The mean floor-likeness (as BoundaryScore gives a strip) of the 3x3 patches (pixels `scale`
// apart) 4 `scale` px below each of `points` along `normal` (unit, pointing toward the floor); -1
// when no patch is inside. `bgr` as for SampleFloor.
double FloorLikenessBelow(const cv::Mat& bgr, const FloorAppearance& floor,
                          const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& normal,
                          int roi_top, int scale = 1);

// How unlike the floor just below `lower` the band between `upper` and `lower` looks: two lines
// through one vanishing point on the same side, `upper` above (on the wall side of) `lower`. The
// median, over samples along their common extent where the band is at least 4 `scale` px tall,
// of the Lab distance between the band's middle and the floor 3 `scale` px below `lower` (means
// of 3x3 pixels `scale` apart), over the floor's spread. Large for a baseboard (its top above,
// the junction below); small for a tile between a junction and a grout line. -1 when fewer than
// 6 samples are usable. `bgr` and `scale` as for BoundaryScore.
double BandContrast(const cv::Mat& bgr, const FloorAppearance& floor, const MergedLine& upper,
                    const MergedLine& lower, int roi_top, int scale = 1);

// How much the band between `upper` and `lower` (as for BandContrast) changes from top to foot:
// the median, over the same samples, of the Lab distance between the band a quarter and three
// quarters of the way down, over that between its middle and the floor 3 `scale` px below
// `lower`. Near 0 for a painted baseboard (one colour top to foot); large for a satin floor's
// reflection, which fades into the floor. -1 when fewer than 6 samples are usable.
double BandFade(const cv::Mat& bgr, const MergedLine& upper, const MergedLine& lower, int roi_top,
                int scale = 1);

}  // namespace corridor
