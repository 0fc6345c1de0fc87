#pragma once

#include <opencv2/core.hpp>

#include "perception/line_segments.h"

namespace corridor {

// The fraction of points along `line` where it is a thin ridge, in [0, 1]: a line darker (or
// lighter) than both of its sides by more than the sides differ from each other, and by at least
// `min_contrast` grey levels. A grout joint or a groove in the floor is one (the floor on both
// sides, the joint darker); a junction is a step from the floor to the wall. The sides are the
// 3x3 means (pixels `scale` apart) 4 `scale` px above and below the line; the line's own grey is
// its darkest (lightest) of the offsets -1, 0, 1 `scale` px, each a mean of 3 pixels along it.
// `bgr`: the ROI rows [roi_top, image rows) of the 8-bit BGR image; -1 when fewer than 6 of the
// 24 points are inside.
double RidgeFraction(const cv::Mat& bgr, const MergedLine& line, int roi_top, int scale = 1,
                     double min_contrast = 6.0);

}  // namespace corridor
