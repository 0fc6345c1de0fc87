#pragma once

// cv::fastAtan2 inline (a private header of perception): the same polynomial in the same order,
// so the same float for every input (the test compares every Sobel gradient); OpenCV's is a call
// into its core library per pixel.

#include <cfloat>
#include <cmath>

namespace corridor {

// The angle of (x, y) in degrees, [0, 360), to about 0.01 degree.
inline float FastAtan2(float y, float x) {
  constexpr float kDegrees = static_cast<float>(180 / M_PI);
  constexpr float p1 = 0.9997878412794807f * kDegrees, p3 = -0.3258083974640975f * kDegrees;
  constexpr float p5 = 0.1555786518463281f * kDegrees, p7 = -0.04432655554792128f * kDegrees;
  const float ax = std::abs(x), ay = std::abs(y);
  float a;
  if (ax >= ay) {
    const float c = ay / (ax + static_cast<float>(DBL_EPSILON)), c2 = c * c;
    a = (((p7 * c2 + p5) * c2 + p3) * c2 + p1) * c;
  } else {
    const float c = ax / (ay + static_cast<float>(DBL_EPSILON)), c2 = c * c;
    a = 90.f - (((p7 * c2 + p5) * c2 + p3) * c2 + p1) * c;
  }
  if (x < 0) a = 180.f - a;
  if (y < 0) a = 360.f - a;
  return a;
}

}  // namespace corridor
