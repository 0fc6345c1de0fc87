// corridor_depth on ROS 1 bags: a bag written by the real rosbag library (python3-rosbag)
// gives the same depth maps as the same frames in a folder, in every supported encoding; bad bags
// get a clear message and exit code 2, never a crash.

#include <filesystem>
#include <fstream>

#include "tests/robotics/robotics_test_data.h"

namespace corridor {
namespace testing_util {
namespace {

struct Encoding {
  std::string name;   // Test name.
  std::string topic;  // Its topic in the bag.
};

// One bag with the three frames on six image topics (rgb8, bgr8, mono8, bgra8, JPEG, PNG), each
// with its CameraInfo beside it, plus a yuv422 topic (unsupported) and a topic without CameraInfo;
// and, for every topic, the same frames as files in a folder with camera.yaml.
class BagInputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    frames_ = MakeTestFrames();
    BagManifest manifest(dir_);
    for (size_t i = 0; i < frames_.images.size(); ++i) {
      const cv::Mat& bgr = frames_.images[i];
      for (const std::string enc : {"rgb8", "bgr8", "mono8", "bgra8"}) {
        const std::string ns = "/" + enc;
        manifest.AddImage(ns + "/image_raw", i, enc, ToEncoding(bgr, enc));
        manifest.AddCameraInfo(ns + "/camera_info", i, frames_.camera);
        // The folder holds the same pixels: PNG in colour, grey, or with alpha.
        dir_.WriteImage("folder_" + enc + "/" + TestStampName(i) + ".png",
                        enc == "rgb8" ? bgr : ToEncoding(bgr, enc));
      }
      for (const std::string fmt : {"jpeg", "png"}) {
        std::vector<uchar> bytes;
        ASSERT_TRUE(cv::imencode(fmt == "jpeg" ? ".jpg" : ".png", bgr, bytes));
        manifest.AddCompressed("/" + fmt + "/image_raw/compressed", i, fmt, bytes);
        manifest.AddCameraInfo("/" + fmt + "/camera_info", i, frames_.camera);
        dir_.Write("folder_" + fmt + "/" + TestStampName(i) + (fmt == "jpeg" ? ".jpg" : ".png"),
                   std::string(bytes.begin(), bytes.end()));
      }
      cv::Mat yuv(bgr.rows, bgr.cols, CV_8UC2, cv::Scalar(128, 128));
      manifest.AddImage("/yuv/image_raw", i, "yuv422", yuv);
      manifest.AddCameraInfo("/yuv/camera_info", i, frames_.camera);
      manifest.AddImage("/bare/image_raw", i, "bgr8", bgr);
    }
    bag_ = manifest.WriteBag("corridor.bag");
    Camera with_height = frames_.camera;
    for (const std::string enc : {"rgb8", "bgr8", "mono8", "bgra8", "jpeg", "png"}) {
      dir_.WriteCamera("folder_" + enc + "/camera.yaml", with_height);
    }
    camera_file_ = dir_.WriteCamera("camera.yaml", with_height);
  }

  std::string Height() const {
    return "--camera_height=" + std::to_string(frames_.camera.mount_height);
  }

  ScratchDir dir_;
  TestFrames frames_;
  std::string bag_;
  std::string camera_file_;
};

TEST_F(BagInputTest, EveryEncodingGivesTheDepthOfTheSameFramesInAFolder) {
  for (const std::string enc : {"rgb8", "bgr8", "mono8", "bgra8", "jpeg", "png"}) {
    SCOPED_TRACE(enc);
    const std::string topic = (enc == "jpeg" || enc == "png") ? "/" + enc + "/image_raw/compressed"
                                                              : "/" + enc + "/image_raw";
    const ToolRun from_bag = RunDepthTool(bag_, dir_.Path("out_bag_" + enc), dir_,
                                          {"--image_topic=" + topic, Height(), "--write_vis=false"});
    ASSERT_EQ(from_bag.exit_code, 0) << from_bag.err;
    const ToolRun from_folder = RunDepthTool(dir_.Path("folder_" + enc),
                                             dir_.Path("out_folder_" + enc), dir_,
                                             {"--write_vis=false"});
    ASSERT_EQ(from_folder.exit_code, 0) << from_folder.err;
    for (size_t i = 0; i < frames_.images.size(); ++i) {
      const std::string name = TestStampName(i) + ".png";
      const cv::Mat a = ReadDepthMm(dir_.Path("out_bag_" + enc + "/corridor/depth/" + name));
      const cv::Mat b = ReadDepthMm(dir_.Path("out_folder_" + enc + "/folder_" + enc +
                                              "/depth/" + name));
      ASSERT_FALSE(a.empty()) << "no depth for bag frame " << name;
      ASSERT_FALSE(b.empty()) << "no depth for folder frame " << name;
      EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << name;
      EXPECT_GT(cv::countNonZero(a), a.total() / 2) << name;
    }
    // geometry.csv gains the stamp of each message.
    const std::string csv = ReadAll(dir_.Path("out_bag_" + enc + "/corridor/geometry.csv"));
    EXPECT_TRUE(Contains(csv.substr(0, csv.find('\n')), ",stamp")) << csv;
    for (size_t i = 0; i < frames_.images.size(); ++i) {
      EXPECT_TRUE(Contains(csv, "," + TestStampName(i) + "\n")) << csv;
    }
  }
}

TEST_F(BagInputTest, CameraInfoGivesTheIntrinsics) {
  const ToolRun run = RunDepthTool(bag_, dir_.Path("out"), dir_,
                                   {"--image_topic=/bgr8/image_raw", Height()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  Camera used;
  ASSERT_TRUE(ReadCameraYaml(dir_.Path("out/corridor/camera_used.yaml"), &used).ok());
  EXPECT_EQ(used.fx, frames_.camera.fx);
  EXPECT_EQ(used.cx, frames_.camera.cx);
  EXPECT_EQ(used.image_width, frames_.camera.image_width);
  EXPECT_EQ(used.mount_height, frames_.camera.mount_height);
}

TEST_F(BagInputTest, SeveralImageTopicsWithoutAChoiceListsThem) {
  const ToolRun run = RunDepthTool(bag_, dir_.Path("out"), dir_, {Height()});
  ExpectCleanExit(run, 2, {bag_, "--image_topic", "/rgb8/image_raw", "/jpeg/image_raw/compressed"});
}

TEST_F(BagInputTest, ATopicThatIsNotThereIsNamed) {
  const ToolRun run = RunDepthTool(bag_, dir_.Path("out"), dir_, {"--image_topic=/nope", Height()});
  ExpectCleanExit(run, 2, {bag_, "/nope", "not in the bag"});
  EXPECT_FALSE(Exists(dir_.Path("out/corridor/depth")));
}

TEST_F(BagInputTest, AnUnsupportedEncodingIsNamed) {
  const ToolRun run =
      RunDepthTool(bag_, dir_.Path("out"), dir_, {"--image_topic=/yuv/image_raw", Height()});
  ExpectCleanExit(run, 2, {bag_, "yuv422", "unsupported"});
}

TEST_F(BagInputTest, NoCameraInfoAndNoCameraIsAConfigurationError) {
  const ToolRun run =
      RunDepthTool(bag_, dir_.Path("out"), dir_, {"--image_topic=/bare/image_raw", Height()});
  ExpectCleanExit(run, 2, {bag_, "CameraInfo", "--camera"});
  // With --camera the same topic works.
  const ToolRun with_camera = RunDepthTool(bag_, dir_.Path("out2"), dir_,
                                           {"--image_topic=/bare/image_raw",
                                            "--camera=" + camera_file_, "--write_vis=false"});
  EXPECT_EQ(with_camera.exit_code, 0) << with_camera.err;
  EXPECT_TRUE(Exists(dir_.Path("out2/corridor/depth/" + TestStampName(2) + ".png")));
}

TEST_F(BagInputTest, ACameraHeightIsRequired) {
  const ToolRun run = RunDepthTool(bag_, dir_.Path("out"), dir_, {"--image_topic=/png/image_raw/compressed"});
  ExpectCleanExit(run, 2, {bag_, "--camera_height"});
}

TEST_F(BagInputTest, ATruncatedBagIsNamed) {
  const std::string whole = ReadAll(bag_);
  const std::string cut = dir_.Write("cut.bag", whole.substr(0, whole.size() * 6 / 10));
  const ToolRun run = RunDepthTool(cut, dir_.Path("out"), dir_, {"--image_topic=/bgr8/image_raw", Height()});
  ExpectCleanExit(run, 2, {cut});
  const std::string text = dir_.Write("text.bag", "this is not a bag\n");
  ExpectCleanExit(RunDepthTool(text, dir_.Path("out"), dir_, {Height()}), 2, {text});
  ExpectCleanExit(RunDepthTool(dir_.Path("missing.bag"), dir_.Path("out"), dir_, {Height()}), 2,
                  {dir_.Path("missing.bag")});
}

}  // namespace
}  // namespace testing_util
}  // namespace corridor
