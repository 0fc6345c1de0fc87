// The detector on the real corridor photographs of tests/data/real-corridors/.
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "perception/junction_detector.h"

namespace corridor {
namespace {

const std::string kDir = std::string(CORRIDOR_SOURCE_DIR) + "/tests/data/real-corridors/";

const char* const kPhotos[] = {"rtabmap_1.jpg", "rtabmap_2.jpg", "rtabmap_3.jpg", "rtabmap_4.jpg",
                               "rtabmap_5.jpg", "rtabmap_6.jpg", "rtabmap_7.jpg", "rtabmap_8.jpg",
                               "popup_1.png", "popup_2.png", "popup_3.png"};

bool Plausible(const JunctionPair& pair, const cv::Size& size) {
  if (!pair.status.ok()) return false;
  const double slope_left = -pair.left.line.x() / pair.left.line.y();
  const double slope_right = -pair.right.line.x() / pair.right.line.y();
  return slope_left < 0 && slope_right > 0 &&
         pair.vanishing_point.y() < std::min(pair.left.far_end.y(), pair.right.far_end.y()) + 3 &&
         pair.vanishing_point.x() > -size.width && pair.vanishing_point.x() < 2 * size.width;
}

// A regression floor for the photographs: both junctions, with the right slopes and the
// vanishing point above them, on all 11 (rtabmap_6's right junction, broken by door bottoms, is
// found by the detector's second, relaxed Hough look).
TEST(RealPhotosTest, BothJunctionsOnMostPhotos) {
  int found = 0;
  for (const char* name : kPhotos) {
    const cv::Mat image = cv::imread(kDir + name);
    ASSERT_FALSE(image.empty()) << name;
    JunctionPair pair;
    ASSERT_TRUE(DetectJunctions(image, JunctionDetectorOptions(), &pair).ok());
    const bool ok = Plausible(pair, image.size());
    found += ok;
    std::printf("%-14s %s\n", name, ok ? "both junctions" : pair.status.ToString().c_str());
  }
  EXPECT_GE(found, 11);
}

}  // namespace
}  // namespace corridor
