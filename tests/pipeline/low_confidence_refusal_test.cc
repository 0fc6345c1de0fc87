// A frame whose confidence is below min_confidence is refused with the weakest factor's reason
// (FrameConfidence's, from the frame's own evidence); with a lower bar the same frame is accepted
// with the same confidence. popup_3 (a real photo) is refused by the default bar.
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "corridor_depth/recover_depth.h"
#include "pipeline/frame_confidence.h"

namespace corridor {
namespace {

TEST(LowConfidenceRefusalTest, TheMessageGivesTheWeakestFactor) {
  const cv::Mat image = cv::imread(std::string(CORRIDOR_SOURCE_DIR) +
                                   "/tests/data/real-corridors/popup_3.png");
  ASSERT_FALSE(image.empty());
  Camera camera;
  camera.image_width = 640;
  camera.image_height = 480;
  camera.fx = camera.fy = 570.342;
  camera.cx = 319.5;
  camera.cy = 239.5;
  camera.mount_height = 1.0;

  RecoverDepthOptions options;
  RecoverDepthResult refused;
  const Status status = RecoverDepth(image, camera, options, &refused);
  ASSERT_EQ(status.code(), StatusCode::kLowConfidence) << status.ToString();
  EXPECT_LT(refused.confidence, options.min_confidence);
  std::string why;
  EXPECT_EQ(FrameConfidence(refused.evidence, &why), refused.confidence);
  EXPECT_NE(why, "the evidence is good");
  const std::string tail = ": " + why;
  ASSERT_GE(status.message().size(), tail.size());
  EXPECT_EQ(status.message().substr(status.message().size() - tail.size()), tail)
      << status.message();

  options.min_confidence = 0;
  RecoverDepthResult accepted;
  ASSERT_TRUE(RecoverDepth(image, camera, options, &accepted).ok())
      << accepted.status.ToString();
  EXPECT_EQ(accepted.confidence, refused.confidence);
}

}  // namespace
}  // namespace corridor
