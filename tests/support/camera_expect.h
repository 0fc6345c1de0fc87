#pragma once

#include <gtest/gtest.h>

#include "corridor_depth/camera.h"

namespace corridor {
namespace testing_util {

// Expects exactly these pinhole intrinsics: size, focal lengths and principal point, px.
inline void ExpectPinhole(const Camera& c, int width, int height, double fx, double fy, double cx,
                          double cy) {
  EXPECT_EQ(c.image_width, width);
  EXPECT_EQ(c.image_height, height);
  EXPECT_EQ(c.fx, fx);
  EXPECT_EQ(c.fy, fy);
  EXPECT_EQ(c.cx, cx);
  EXPECT_EQ(c.cy, cy);
}

}  // namespace testing_util
}  // namespace corridor
