#pragma once

// The mean colour of an 8-bit BGR image at points spaced along a ray: the inner loop of the colour
// profiles that the searches for a baseboard's foot and a polished floor's reflection read
// (perception/band_profile.h).

#include <opencv2/core.hpp>

namespace corridor {

// The mean colour of the 8-bit BGR `roi`'s pixels nearest the image points (x0 + r dx, y0 + r dy),
// r in radii[0 .. count) (count > 0). `roi` holds the image's rows [roi_top, roi_top + roi.rows).
// Each point is rounded half away from zero (RoundHalfAway; a coordinate beyond 1e9 or not a number
// as -1) and clamped into the roi. Bit for bit the result of summing the pixels as doubles in order
// and dividing the sum by the count with cv::Vec3d's division.
cv::Vec3d MeanColourAtRadii(const cv::Mat& roi, int roi_top, double x0, double y0, double dx,
                            double dy, const double* radii, int count);

}  // namespace corridor
