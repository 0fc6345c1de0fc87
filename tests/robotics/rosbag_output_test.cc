// corridor_depth --output_bag: the depth bag reads back with the real rosbag library (topics,
// types, encodings, stamps, frame_id, pixels, CameraInfo), in the live node's conventions:
// <prefix>/depth/image and <prefix>/depth/camera_info, 32FC1 metres with NaN = none by default.

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <cmath>
#include <cstring>
#include <map>

#include "io/rosbag_io.h"
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

// The topic types of a bag, by topic.
std::map<std::string, std::string> TopicTypes(rosbag::Bag& bag) {
  std::map<std::string, std::string> types;
  rosbag::View all(bag);
  for (const rosbag::ConnectionInfo* c : all.getConnections()) types[c->topic] = c->datatype;
  return types;
}

// Pixel p of a little-endian 32FC1 image message.
float FloatAt(const sensor_msgs::Image& image, cv::Point p) {
  const size_t at = static_cast<size_t>(p.y) * image.step + 4 * static_cast<size_t>(p.x);
  const uint32_t bits = image.data[at] | (image.data[at + 1] << 8) | (image.data[at + 2] << 16) |
                        (static_cast<uint32_t>(image.data[at + 3]) << 24);
  float value;
  std::memcpy(&value, &bits, 4);
  return value;
}

TEST(DepthTopicPrefixTest, ParentNamespaceWithoutTransport) {
  EXPECT_EQ(DepthTopicPrefix("/cam/image_raw"), "/cam");
  EXPECT_EQ(DepthTopicPrefix("/cam/image_raw/compressed"), "/cam");
  EXPECT_EQ(DepthTopicPrefix("/robot/front/image_rect_color/theora"), "/robot/front");
  EXPECT_EQ(DepthTopicPrefix("/image"), "/");
  EXPECT_EQ(DepthTopicPrefix("/image/compressed"), "/");
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
  const std::string depth_topic = "/cam/depth/image";
  const std::string info_topic = "/cam/depth/camera_info";
  std::map<std::string, std::string> types = TopicTypes(read);
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
    EXPECT_EQ(image->encoding, "32FC1");
    EXPECT_EQ(image->is_bigendian, 0);
    ASSERT_EQ(image->width, 320u);
    ASSERT_EQ(image->height, 240u);
    ASSERT_EQ(image->step, 1280u);
    // Pixels: the depth PNG's millimetres in metres, NaN where the PNG has none.
    const cv::Mat png = ReadDepthMm(dir.Path("out/single/depth/" + TestStampName(i) + ".png"));
    ASSERT_EQ(png.type(), CV_16UC1);
    int none = 0;
    for (int y = 0; y < png.rows; ++y) {
      for (int x = 0; x < png.cols; ++x) {
        const float metres = FloatAt(*image, {x, y});
        const int mm = png.at<uint16_t>(y, x);
        if (mm == 0) {
          ++none;
          ASSERT_TRUE(std::isnan(metres)) << x << "," << y << ": " << metres;
        } else {
          ASSERT_NEAR(metres * 1000.0, mm, 0.5 + 1e-3) << x << "," << y;
        }
      }
    }
    EXPECT_GT(none, 0);  // The generated corridor's far end has no estimate.
    // And the true depth there, within 5%.
    const float truth = frames.depths[i].at<float>(220, 160);
    EXPECT_NEAR(FloatAt(*image, {160, 220}), truth, 0.05 * truth);
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

// --depth_encoding=16UC1 and --output_bag_prefix: millimetres equal to the depth PNG's, under the
// prefix; the input's compressed transport does not reach the default prefix.
TEST(OutputBagTest, MillimetresUnderAPrefix) {
  ScratchDir dir;
  const TestFrames frames = MakeTestFrames();
  BagManifest manifest(dir);
  for (size_t i = 0; i < frames.images.size(); ++i) {
    manifest.AddCameraInfo("/cam/camera_info", i, frames.camera);
    std::vector<uint8_t> png;
    cv::imencode(".png", frames.images[i], png);
    manifest.AddCompressed("/cam/image_raw/compressed", i, "png", png);
  }
  const std::string bag = manifest.WriteBag("compressed.bag");
  for (const std::string prefix : {"", "/robot/front/"}) {
    const std::string out_bag = dir.Path("depth_mm" + std::to_string(prefix.size()) + ".bag");
    std::vector<std::string> flags = {"--camera_height=1.2", "--output_bag=" + out_bag,
                                      "--depth_encoding=16UC1"};
    if (!prefix.empty()) flags.push_back("--output_bag_prefix=" + prefix);
    const ToolRun run = RunDepthTool(bag, dir.Path("out_mm"), dir, flags);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::string base = prefix.empty() ? "/cam" : "/robot/front";
    rosbag::Bag read(out_bag, rosbag::bagmode::Read);
    std::map<std::string, std::string> types = TopicTypes(read);
    ASSERT_EQ(types.size(), 2u);
    EXPECT_EQ(types[base + "/depth/image"], "sensor_msgs/Image");
    EXPECT_EQ(types[base + "/depth/camera_info"], "sensor_msgs/CameraInfo");
    size_t i = 0;
    for (const rosbag::MessageInstance& m :
         rosbag::View(read, rosbag::TopicQuery(base + "/depth/image"))) {
      const auto image = m.instantiate<sensor_msgs::Image>();
      ASSERT_TRUE(image);
      EXPECT_EQ(image->encoding, "16UC1");
      ASSERT_EQ(image->step, 640u);
      const cv::Mat png =
          ReadDepthMm(dir.Path("out_mm/compressed/depth/" + TestStampName(i) + ".png"));
      ASSERT_EQ(png.type(), CV_16UC1);
      for (const cv::Point p : {cv::Point(160, 220), cv::Point(10, 120), cv::Point(300, 60)}) {
        const size_t at = static_cast<size_t>(p.y) * image->step + 2 * p.x;
        EXPECT_EQ(image->data[at] | (image->data[at + 1] << 8), png.at<uint16_t>(p)) << p;
      }
      ++i;
    }
    EXPECT_EQ(i, frames.images.size());
  }
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
