// corridor_depth --output_bag: the depth bag reads back with the real rosbag library
// (topics, types, encodings, stamps, frame_id, pixels, CameraInfo).

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <map>

#include "tests/robotics/robotics_test_data.h"

namespace corridor {
namespace testing_util {
namespace {

constexpr char kTopic[] = "/cam/image_raw";

// A bag with the three frames on /cam/image_raw (rgb8) and their CameraInfo on /cam/camera_info.
std::string WriteSingleTopicBag(const ScratchDir& dir, const TestFrames& frames) {
  BagManifest manifest(dir);
  for (size_t i = 0; i < frames.images.size(); ++i) {
    manifest.AddCameraInfo("/cam/camera_info", i, frames.camera);
    manifest.AddImage(kTopic, i, "rgb8", ToEncoding(frames.images[i], "rgb8"));
  }
  return manifest.WriteBag("single.bag");
}

TEST(OutputBagTest, ReadsBackWithTheRosbagLibrary) {
  ScratchDir dir;
  const TestFrames frames = MakeTestFrames();
  const std::string bag = WriteSingleTopicBag(dir, frames);
  const std::string out_bag = dir.Path("depth.bag");
  // No --image_topic and no --camera: the only image topic, the CameraInfo beside it.
  const ToolRun run = RunDepthTool(bag, dir.Path("out"), dir,
                                   {"--camera_height=1.2", "--output_bag=" + out_bag});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(Exists(out_bag + ".part"));

  rosbag::Bag read(out_bag, rosbag::bagmode::Read);
  const std::string depth_topic = std::string(kTopic) + "/corridor_depth";
  const std::string info_topic = depth_topic + "/camera_info";
  std::map<std::string, std::string> types;
  rosbag::View all(read);
  for (const rosbag::ConnectionInfo* c : all.getConnections()) types[c->topic] = c->datatype;
  ASSERT_EQ(types.size(), 2u);
  EXPECT_EQ(types[depth_topic], "sensor_msgs/Image");
  EXPECT_EQ(types[info_topic], "sensor_msgs/CameraInfo");

  size_t i = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(read, rosbag::TopicQuery(depth_topic))) {
    ASSERT_LT(i, frames.images.size());
    const auto image = m.instantiate<sensor_msgs::Image>();
    ASSERT_TRUE(image);
    EXPECT_EQ(image->header.stamp.sec, TestStamp(i).first);
    EXPECT_EQ(image->header.stamp.nsec, TestStamp(i).second);
    EXPECT_EQ(m.getTime(), image->header.stamp);
    EXPECT_EQ(image->header.frame_id, "test_camera");
    EXPECT_EQ(image->encoding, "16UC1");
    EXPECT_EQ(image->is_bigendian, 0);
    ASSERT_EQ(image->width, 320u);
    ASSERT_EQ(image->height, 240u);
    ASSERT_EQ(image->step, 640u);
    // Pixels: the depth PNG's millimetres, little-endian, at a floor and a wall pixel.
    const cv::Mat png = ReadDepthMm(dir.Path("out/single/depth/" + TestStampName(i) + ".png"));
    ASSERT_EQ(png.type(), CV_16UC1);
    for (const cv::Point p : {cv::Point(160, 220), cv::Point(10, 120), cv::Point(300, 60)}) {
      const size_t at = static_cast<size_t>(p.y) * image->step + 2 * p.x;
      const int value = image->data[at] | (image->data[at + 1] << 8);
      EXPECT_EQ(value, png.at<uint16_t>(p)) << p;
    }
    // And the true depth there, within 5%.
    const float truth = frames.depths[i].at<float>(220, 160);
    const int floor = image->data[220 * 640 + 320] | (image->data[220 * 640 + 321] << 8);
    EXPECT_NEAR(floor * 1e-3, truth, 0.05 * truth);
    ++i;
  }
  EXPECT_EQ(i, frames.images.size());
  size_t infos = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(read, rosbag::TopicQuery(info_topic))) {
    const auto info = m.instantiate<sensor_msgs::CameraInfo>();
    ASSERT_TRUE(info);
    EXPECT_EQ(info->header.stamp.sec, TestStamp(infos).first);
    EXPECT_EQ(info->header.stamp.nsec, TestStamp(infos).second);
    EXPECT_EQ(info->K[0], frames.camera.fx);
    EXPECT_EQ(info->K[2], frames.camera.cx);
    EXPECT_EQ(info->width, 320u);
    ++infos;
  }
  EXPECT_EQ(infos, frames.images.size());
}

TEST(OutputBagTest, DoesNotGoWithSkipExisting) {
  ScratchDir dir;
  const TestFrames frames = MakeTestFrames();
  const std::string bag = WriteSingleTopicBag(dir, frames);
  ExpectCleanExit(RunDepthTool(bag, dir.Path("out"), dir,
                               {"--camera_height=1.2", "--output_bag=" + dir.Path("d.bag"),
                                "--skip_existing"}),
                  2, {"--output_bag", "--skip_existing"});
}

}  // namespace
}  // namespace testing_util
}  // namespace corridor
