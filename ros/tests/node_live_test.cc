// corridor_depth_node live, end to end: a ROS master of its own on a free loopback port, the node,
// and this test as camera and consumer. A generated 30-frame corridor sequence goes in, each frame
// after the previous depth came back, with bad frames in the middle; the depth, its camera_info
// and points that come back are checked against the generator's truth, against corridor_depth on
// the same frames, and against points made here from the message definitions alone.

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_msgs/TFMessage.h>

#include "corridor_depth/depth_metrics.h"
#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/image_io.h"
#include "ros/tests/ros_test_process.h"

namespace corridor {
namespace testing_util {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kNode = CORRIDOR_BINARY_DIR "/ros/corridor_depth_node";
const std::string kSynth = CORRIDOR_BINARY_DIR "/tools/corridor_synth";
const std::string kDepthTool = CORRIDOR_BINARY_DIR "/tools/corridor_depth";
constexpr int kFrames = 30;
constexpr char kFrameId[] = "cam_optical";

// A folder of its own under the test temp dir, removed at the end.
struct Scratch {
  Scratch() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root = fs::path(::testing::TempDir()) /
           (std::string("corridor_node_") + info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
  std::string Path(const std::string& relative) const { return (root / relative).string(); }
  fs::path root;
};

// Runs a tool to completion; its exit code (-1 when it did not exit normally).
int RunToCompletion(const std::vector<std::string>& argv, const std::string& log) {
  ChildProcess child(argv, log);
  if (!child.started()) return -1;
  for (int i = 0; i < 1800 && child.Running(); ++i) {  // At most 3 minutes.
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const int status = child.Stop();
  return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A 32FC1 or 16UC1 depth message as CV_32F metres, 0 = none: written against the message
// definition (little-endian rows of `step` bytes).
cv::Mat DepthFromMessage(const sensor_msgs::Image& image) {
  cv::Mat depth(static_cast<int>(image.height), static_cast<int>(image.width), CV_32F);
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) {
      const uint8_t* p = image.data.data() + static_cast<size_t>(r) * image.step;
      float value = 0;
      if (image.encoding == "32FC1") {
        const uint32_t bits = p[4 * c] | (p[4 * c + 1] << 8) | (p[4 * c + 2] << 16) |
                              (static_cast<uint32_t>(p[4 * c + 3]) << 24);
        std::memcpy(&value, &bits, 4);
        if (!std::isfinite(value)) value = 0;
      } else {
        value = static_cast<float>((p[2 * c] | (p[2 * c + 1] << 8)) * 1e-3);
      }
      depth.at<float>(r, c) = value;
    }
  }
  return depth;
}

// Field `name` of point i of a PointCloud2, read by its PointField (FLOAT32 only).
float CloudField(const sensor_msgs::PointCloud2& cloud, size_t i, const std::string& name) {
  for (const auto& field : cloud.fields) {
    if (field.name != name) continue;
    EXPECT_EQ(field.datatype, sensor_msgs::PointField::FLOAT32);
    float value;
    std::memcpy(&value, cloud.data.data() + i * cloud.point_step + field.offset, 4);
    return value;
  }
  ADD_FAILURE() << "no field " << name;
  return 0;
}

std::string StampKey(const ros::Time& t) { return std::to_string(t.toNSec()); }

std::string Value(const diagnostic_msgs::DiagnosticStatus& status, const std::string& key) {
  for (const auto& pair : status.values) {
    if (pair.key == key) return pair.value;
  }
  return "";
}

// What came back from the node, by stamp.
struct Received {
  std::mutex mutex;
  std::map<std::string, sensor_msgs::ImageConstPtr> depth;
  std::map<std::string, sensor_msgs::CameraInfoConstPtr> info;
  std::map<std::string, sensor_msgs::PointCloud2ConstPtr> points;
  std::map<std::string, diagnostic_msgs::DiagnosticStatus> geometry;
  diagnostic_msgs::DiagnosticStatus last_diagnostics;
  int diagnostics = 0;

  template <class Map>
  bool Has(Map& map, const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex);
    return map.count(key) > 0;
  }
};

// Every wait of a test ends by this time: a test never hangs on a silent node.
Clock::time_point g_deadline = Clock::time_point::max();

// Waits until `done` holds, up to `seconds` (and the test's deadline); whether it held.
template <class F>
bool WaitFor(F done, double seconds) {
  const auto wait = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(seconds));
  const auto end = std::min(g_deadline, Clock::now() + wait);
  while (Clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return done();
}

// The ROS master of this test process, on a free loopback port, with ROS_MASTER_URI set here
// and inherited by the node. ctest runs each test in a process of its own, so each gets its own
// master; a process that runs several tests shares one (roscpp initialises once per process).
class Master {
 public:
  static Master& Get() {
    if (instance_ == nullptr) instance_ = new Master();
    return *instance_;
  }
  // Shuts roscpp down and stops the master, if one was started (after the last test).
  static void Stop() {
    delete instance_;
    instance_ = nullptr;
  }
  // True once the master answers (waits up to 20 s the first time).
  bool Ready() {
    if (!started_) {
      started_ = true;
      int argc = 0;
      ros::init(argc, nullptr, "corridor_node_test",
                ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
      ready_ = process_->started() && WaitFor([] { return ros::master::check(); }, 20);
    }
    return ready_;
  }
  std::string Log() const { return ReadText(dir_.string() + "/master.log"); }
  ~Master() {
    if (ros::isStarted()) ros::shutdown();
    process_->Stop();
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

 private:
  Master() {
    dir_ = fs::path(::testing::TempDir()) / ("corridor_master_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    const int port = FreeLoopbackPort();
    const std::string uri = "http://127.0.0.1:" + std::to_string(port);
    ::setenv("ROS_MASTER_URI", uri.c_str(), 1);
    ::setenv("ROS_IP", "127.0.0.1", 1);
    ::unsetenv("ROS_HOSTNAME");
    ::setenv("ROS_HOME", (dir_ / "ros_home").c_str(), 1);
    ::setenv("ROS_LOG_DIR", (dir_ / "ros_log").c_str(), 1);
    process_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{"rosmaster", "--core", "-p", std::to_string(port)},
        (dir_ / "master.log").string());
  }
  static Master* instance_;
  fs::path dir_;
  std::unique_ptr<ChildProcess> process_;
  bool started_ = false, ready_ = false;
};
Master* Master::instance_ = nullptr;

class StopMaster : public ::testing::Environment {
 public:
  void TearDown() override { Master::Stop(); }
};
const ::testing::Environment* const kStopMaster =
    ::testing::AddGlobalTestEnvironment(new StopMaster);

// The node, started here against this process's master; stopped when this goes.
class LiveNode {
 public:
  LiveNode(const Scratch& dir, const std::vector<std::string>& node_args) {
    // A name of its own: private parameters given on a command line stay on the master.
    static int started = 0;
    node_args_ = {kNode, "__name:=corridor_depth_" + std::to_string(started++), "__ns:=/cd",
                  "image:=/cam/image_raw"};
    node_args_.insert(node_args_.end(), node_args.begin(), node_args.end());
    node_log_ = dir.Path("node.log");
  }
  // Starts the node once the master answers; false when it does not.
  bool Start() {
    if (!Master::Get().Ready()) return false;
    node_ = std::make_unique<ChildProcess>(node_args_, node_log_);
    return node_->started();
  }
  bool NodeRunning() { return node_ && node_->Running(); }
  // The exit code once the node has ended by itself (-1 otherwise).
  int ExitCode() {
    if (!node_ || node_->Running()) return -1;
    const int status = node_->Stop();
    return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string NodeLog() const { return ReadText(node_log_); }
  ~LiveNode() {
    if (node_) node_->Stop();
  }

 private:
  std::unique_ptr<ChildProcess> node_;
  std::vector<std::string> node_args_;
  std::string node_log_;
};

// The generated sequence: frames, truth, camera (with its height), and corridor_depth's depth.
struct Sequence {
  Camera camera;
  std::vector<cv::Mat> images, truth, tool_depth;
};

void MakeSequence(const Scratch& dir, Sequence* sequence, int frames = kFrames) {
  const std::string data = dir.Path("data");
  ASSERT_EQ(RunToCompletion({kSynth, "--preset=sequence", "--frames=" + std::to_string(frames),
                             "--output_dir=" + data},
                            dir.Path("synth.log")),
            0)
      << ReadText(dir.Path("synth.log"));
  // corridor_depth on the same frames as one stream. A build without --sequence treats every
  // input as one stream: it refuses the flag (exit 2, "unknown flag") and runs without it.
  std::vector<std::string> run = {kDepthTool, "--input=" + data,
                                  "--output_dir=" + dir.Path("tool"), "--write_vis=false",
                                  "--sequence=true"};
  int tool_exit = RunToCompletion(run, dir.Path("tool.log"));
  if (tool_exit == 2 && ReadText(dir.Path("tool.log")).find("unknown flag '--sequence") !=
                            std::string::npos) {
    run.pop_back();
    tool_exit = RunToCompletion(run, dir.Path("tool.log"));
  }
  ASSERT_EQ(tool_exit, 0) << ReadText(dir.Path("tool.log"));
  ASSERT_TRUE(ReadCameraYaml(data + "/corridor/camera.yaml", &sequence->camera).ok());
  for (int i = 0; i < frames; ++i) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d.png", i);
    sequence->images.push_back(cv::imread(data + "/corridor/rgb/" + name, cv::IMREAD_COLOR));
    ASSERT_FALSE(sequence->images.back().empty()) << name;
    cv::Mat truth, tool;
    ASSERT_TRUE(ReadDepthPng(data + "/corridor/depth/" + name, &truth).ok()) << name;
    ASSERT_TRUE(ReadDepthPng(dir.Path("tool/corridor/depth/") + name, &tool).ok()) << name;
    sequence->truth.push_back(truth);
    sequence->tool_depth.push_back(tool);
  }
}

sensor_msgs::ImagePtr ImageMessage(const cv::Mat& bgr, const ros::Time& stamp) {
  auto image = boost::make_shared<sensor_msgs::Image>();
  image->header.stamp = stamp;
  image->header.frame_id = kFrameId;
  image->height = static_cast<uint32_t>(bgr.rows);
  image->width = static_cast<uint32_t>(bgr.cols);
  image->encoding = "bgr8";
  image->step = static_cast<uint32_t>(bgr.cols * 3);
  image->data.resize(static_cast<size_t>(image->step) * image->height);
  for (int r = 0; r < bgr.rows; ++r) {
    std::memcpy(image->data.data() + static_cast<size_t>(r) * image->step, bgr.ptr(r),
                image->step);
  }
  return image;
}

sensor_msgs::CameraInfoPtr InfoMessage(const Camera& c, const ros::Time& stamp) {
  auto info = boost::make_shared<sensor_msgs::CameraInfo>();
  info->header.stamp = stamp;
  info->header.frame_id = kFrameId;
  info->width = static_cast<uint32_t>(c.image_width);
  info->height = static_cast<uint32_t>(c.image_height);
  info->distortion_model = "plumb_bob";
  info->D = {0, 0, 0, 0, 0};
  info->K = {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
  info->R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info->P = {c.fx, 0, c.cx, 0, 0, c.fy, c.cy, 0, 0, 0, 1, 0};
  return info;
}

// The test's side of the graph: camera publishers and subscribers to everything the node sends.
struct Graph {
  // `points`: the node publishes depth/points, so wait for it too.
  Graph(Received* received, bool with_points) : points(with_points) {
    const std::string ns = "/cd";
    ros::NodeHandle nh;
    image = nh.advertise<sensor_msgs::Image>("/cam/image_raw", 5);
    info = nh.advertise<sensor_msgs::CameraInfo>("/cam/camera_info", 5);
    subscribers.push_back(nh.subscribe<sensor_msgs::Image>(
        ns + "/depth/image", 50, [received](const sensor_msgs::ImageConstPtr& m) {
          std::lock_guard<std::mutex> lock(received->mutex);
          received->depth[StampKey(m->header.stamp)] = m;
        }));
    subscribers.push_back(nh.subscribe<sensor_msgs::CameraInfo>(
        ns + "/depth/camera_info", 50, [received](const sensor_msgs::CameraInfoConstPtr& m) {
          std::lock_guard<std::mutex> lock(received->mutex);
          received->info[StampKey(m->header.stamp)] = m;
        }));
    subscribers.push_back(nh.subscribe<sensor_msgs::PointCloud2>(
        ns + "/depth/points", 50, [received](const sensor_msgs::PointCloud2ConstPtr& m) {
          std::lock_guard<std::mutex> lock(received->mutex);
          received->points[StampKey(m->header.stamp)] = m;
        }));
    subscribers.push_back(nh.subscribe<diagnostic_msgs::DiagnosticStatus>(
        ns + "/corridor/geometry", 50,
        [received](const diagnostic_msgs::DiagnosticStatusConstPtr& m) {
          std::lock_guard<std::mutex> lock(received->mutex);
          received->geometry[Value(*m, "stamp")] = *m;
        }));
    subscribers.push_back(nh.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 50, [received](const diagnostic_msgs::DiagnosticArrayConstPtr& m) {
          for (const auto& status : m->status) {
            if (status.name.find("corridor_depth") == std::string::npos) continue;
            std::lock_guard<std::mutex> lock(received->mutex);
            received->last_diagnostics = status;
            ++received->diagnostics;
          }
        }));
    spinner = std::make_unique<ros::AsyncSpinner>(1);
    spinner->start();
  }
  // Every link to the node is up.
  bool Connected() const {
    if (image.getNumSubscribers() == 0 || info.getNumSubscribers() == 0) return false;
    for (size_t i = 0; i + 1 < subscribers.size(); ++i) {  // Not /diagnostics: it may be idle.
      if (i == 2 && !points) continue;
      if (subscribers[i].getNumPublishers() == 0) return false;
    }
    return true;
  }
  void Publish(const sensor_msgs::ImagePtr& frame, const sensor_msgs::CameraInfoPtr& camera) {
    info.publish(camera);
    image.publish(frame);
  }
  bool points;
  ros::Publisher image, info;
  std::vector<ros::Subscriber> subscribers;
  std::unique_ptr<ros::AsyncSpinner> spinner;
};

// "<sec>.<nsec>" as the node writes stamps in corridor/geometry.
std::string StampText(const ros::Time& t) {
  char text[32];
  std::snprintf(text, sizeof(text), "%u.%09u", t.sec, t.nsec);
  return text;
}

TEST(NodeLiveTest, SequenceDepthPointsAndBadFrames) {
  Scratch dir;
  Sequence sequence;
  MakeSequence(dir, &sequence);
  if (HasFatalFailure()) return;
  char height[32];
  std::snprintf(height, sizeof(height), "%.9g", sequence.camera.mount_height);
  g_deadline = Clock::now() + std::chrono::minutes(5);
  LiveNode live(dir, {std::string("_camera_height:=") + height, "_publish_points:=true",
                      "_points_stride:=1", "_diagnostics_period:=0.5"});
  ASSERT_TRUE(live.Start()) << "no ROS master:\n"
                            << Master::Get().Log();
  Received received;
  Graph graph(&received, true);
  ASSERT_TRUE(WaitFor([&] { return graph.Connected(); }, 30)) << live.NodeLog();

  // The 30 frames, and after frame 14 three bad ones: all black, an image whose size is not
  // camera_info's, and a camera_info with zero focal length.
  const Camera& camera = sequence.camera;
  std::vector<ros::Time> good;
  std::vector<std::pair<ros::Time, std::string>> bad;  // Stamp and what its note must name.
  ros::Time stamp(1700000000, 0);
  const auto next_stamp = [&] { return stamp += ros::Duration(0, 100000000); };
  const auto send_and_wait = [&](const sensor_msgs::ImagePtr& frame,
                                 const sensor_msgs::CameraInfoPtr& info) {
    graph.Publish(frame, info);
    return WaitFor([&] { return received.Has(received.geometry, StampText(frame->header.stamp)); },
                   20);
  };
  for (int i = 0; i < kFrames; ++i) {
    const ros::Time t = next_stamp();
    ASSERT_TRUE(send_and_wait(ImageMessage(sequence.images[i], t), InfoMessage(camera, t)))
        << "frame " << i << ": nothing came back\n"
        << live.NodeLog();
    const std::string key = StampKey(t);
    ASSERT_TRUE(WaitFor([&] {
      return received.Has(received.depth, key) && received.Has(received.info, key) &&
             received.Has(received.points, key);
    },
                        20))
        << "frame " << i << ": no depth, camera_info or points\n"
        << live.NodeLog();
    good.push_back(t);
    if (i == 14) {
      ros::Time b = next_stamp();
      cv::Mat black(camera.image_height, camera.image_width, CV_8UC3, cv::Scalar::all(0));
      ASSERT_TRUE(send_and_wait(ImageMessage(black, b), InfoMessage(camera, b)));
      bad.emplace_back(b, "refused");
      b = next_stamp();
      cv::Mat small;
      cv::resize(sequence.images[i], small, cv::Size(camera.image_width / 2, camera.image_height / 2));
      ASSERT_TRUE(send_and_wait(ImageMessage(small, b), InfoMessage(camera, b)));
      bad.emplace_back(b, "camera_info is 640x480 but the image is 320x240");
      b = next_stamp();
      auto zero = InfoMessage(camera, b);
      zero->K[0] = zero->K[4] = 0;
      ASSERT_TRUE(send_and_wait(ImageMessage(sequence.images[i], b), zero));
      bad.emplace_back(b, "focal length");
    }
  }
  EXPECT_TRUE(live.NodeRunning());

  // The bad frames: no depth, and corridor/geometry says why.
  for (const auto& [t, why] : bad) {
    std::lock_guard<std::mutex> lock(received.mutex);
    EXPECT_EQ(received.depth.count(StampKey(t)), 0u);
    const auto& geometry = received.geometry[StampText(t)];
    EXPECT_NE(Value(geometry, "status"), "ok");
    EXPECT_NE(geometry.level, diagnostic_msgs::DiagnosticStatus::OK);
    const std::string text = Value(geometry, "status") + " " + Value(geometry, "note");
    EXPECT_NE(text.find(why), std::string::npos) << text;
  }

  // The good frames: stamps, frame_id, camera_info, depth against truth and corridor_depth, and
  // points against the ones made here from depth + camera_info (depth_image_proc's formula).
  std::vector<DepthMetrics> node_metrics, tool_metrics;
  double worst_point = 0, lowest_confidence = 1;
  std::map<std::string, sensor_msgs::ImageConstPtr> depths;
  std::map<std::string, sensor_msgs::CameraInfoConstPtr> infos;
  std::map<std::string, sensor_msgs::PointCloud2ConstPtr> clouds;
  {
    std::lock_guard<std::mutex> lock(received.mutex);
    depths = received.depth;
    infos = received.info;
    clouds = received.points;
  }
  EXPECT_EQ(depths.size(), static_cast<size_t>(kFrames));
  for (int i = 0; i < kFrames; ++i) {
    const std::string key = StampKey(good[i]);
    const sensor_msgs::Image& depth = *depths[key];
    const sensor_msgs::CameraInfo& info = *infos[key];
    const sensor_msgs::PointCloud2& cloud = *clouds[key];
    EXPECT_EQ(depth.header.frame_id, kFrameId);
    EXPECT_EQ(info.header.frame_id, kFrameId);
    EXPECT_EQ(cloud.header.frame_id, kFrameId);
    EXPECT_EQ(depth.encoding, "32FC1");
    {
      std::lock_guard<std::mutex> lock(received.mutex);
      const auto& geometry = received.geometry[StampText(good[i])];
      EXPECT_EQ(Value(geometry, "status"), "ok");
      const double confidence = std::atof(Value(geometry, "confidence").c_str());
      EXPECT_GT(confidence, 0.0);
      EXPECT_LE(confidence, 1.0);
      EXPECT_GT(std::atof(Value(geometry, "width_m").c_str()), 0.5);
      lowest_confidence = std::min(lowest_confidence, confidence);
    }
    ASSERT_EQ(depth.width, static_cast<uint32_t>(camera.image_width));
    ASSERT_EQ(depth.height, static_cast<uint32_t>(camera.image_height));
    EXPECT_EQ(info.width, depth.width);
    EXPECT_EQ(info.height, depth.height);
    EXPECT_DOUBLE_EQ(info.K[0], camera.fx);
    EXPECT_DOUBLE_EQ(info.K[4], camera.fy);
    EXPECT_DOUBLE_EQ(info.K[2], camera.cx);
    EXPECT_DOUBLE_EQ(info.K[5], camera.cy);
    EXPECT_DOUBLE_EQ(info.P[0], camera.fx);
    const cv::Mat metres = DepthFromMessage(depth);
    node_metrics.push_back(ComputeDepthMetrics(metres, sequence.truth[i], 40.0));
    tool_metrics.push_back(ComputeDepthMetrics(sequence.tool_depth[i], sequence.truth[i], 40.0));
    ASSERT_EQ(cloud.width, depth.width);
    ASSERT_EQ(cloud.height, depth.height);
    const double fx = info.K[0], fy = info.K[4], cx = info.K[2], cy = info.K[5];
    int nan_points = 0;
    for (int v = 0; v < metres.rows; ++v) {
      for (int u = 0; u < metres.cols; ++u) {
        const size_t at = static_cast<size_t>(v) * cloud.width + static_cast<size_t>(u);
        const float z = metres.at<float>(v, u);
        const float px = CloudField(cloud, at, "x"), py = CloudField(cloud, at, "y"),
                    pz = CloudField(cloud, at, "z");
        if (z == 0) {
          ASSERT_TRUE(std::isnan(px) && std::isnan(py) && std::isnan(pz)) << u << "," << v;
          ++nan_points;
          continue;
        }
        const double ex = (u - cx) * z / fx, ey = (v - cy) * z / fy;
        worst_point = std::max({worst_point, std::abs(px - ex), std::abs(py - ey),
                                std::abs(static_cast<double>(pz) - z)});
      }
    }
    EXPECT_EQ(cloud.is_dense, nan_points == 0);
  }
  EXPECT_LT(worst_point, 1e-5);
  const DepthMetrics node = AverageDepthMetrics(node_metrics);
  const DepthMetrics tool = AverageDepthMetrics(tool_metrics);
  std::printf(
      "[ node     ] AbsRel node %.5f, corridor_depth %.5f; coverage %.4f / %.4f; "
      "worst point difference %.2g m; lowest confidence %.3f\n",
      node.abs_rel, tool.abs_rel, node.coverage, tool.coverage, worst_point,
      lowest_confidence);
  EXPECT_NEAR(node.abs_rel, tool.abs_rel, 0.01);
  EXPECT_LT(node.abs_rel, 0.1);  // And a corridor, not an empty map.
  EXPECT_GT(node.coverage, 0.5);

  // /diagnostics: every frame counted, none dropped (each was sent after the previous came back),
  // the three bad ones named, latency reported.
  const bool counted = WaitFor([&] {
    std::lock_guard<std::mutex> lock(received.mutex);
    const auto& d = received.last_diagnostics;
    return Value(d, "frames_published") == std::to_string(kFrames) &&
           Value(d, "frames_received") == std::to_string(kFrames + 3);
  },
                               10);
  diagnostic_msgs::DiagnosticStatus diagnostics;
  {
    std::lock_guard<std::mutex> lock(received.mutex);
    diagnostics = received.last_diagnostics;
  }
  EXPECT_TRUE(counted) << "frames_published " << Value(diagnostics, "frames_published")
                       << ", frames_received " << Value(diagnostics, "frames_received");
  EXPECT_EQ(Value(diagnostics, "frames_dropped"), "0");
  EXPECT_EQ(std::atoi(Value(diagnostics, "frames_refused").c_str()) +
                std::atoi(Value(diagnostics, "frames_failed").c_str()),
            3);
  EXPECT_EQ(Value(diagnostics, "last_problem_stamp"), StampText(bad.back().first));
  EXPECT_GT(std::atof(Value(diagnostics, "latency_median_s").c_str()), 0.0);
  EXPECT_GE(std::atof(Value(diagnostics, "latency_p99_s").c_str()),
            std::atof(Value(diagnostics, "latency_median_s").c_str()));
}

// ~base_frame: the camera height from TF (a static base_footprint -> camera transform). A frame
// before the transform exists gets no depth and says why; the frames after it do, with the height.
// Also ~depth_encoding:=16UC1 and ~sequence:=false (independent frames).
TEST(NodeLiveTest, CameraHeightFromTf) {
  Scratch dir;
  Sequence sequence;
  MakeSequence(dir, &sequence, 3);
  if (HasFatalFailure()) return;
  g_deadline = Clock::now() + std::chrono::minutes(3);
  LiveNode live(dir, {"_base_frame:=base_footprint", "_depth_encoding:=16UC1", "_sequence:=false"});
  ASSERT_TRUE(live.Start()) << "no ROS master:\n"
                            << Master::Get().Log();
  Received received;
  Graph graph(&received, false);
  ASSERT_TRUE(WaitFor([&] { return graph.Connected(); }, 30)) << live.NodeLog();
  const Camera& camera = sequence.camera;
  const auto send_and_wait = [&](int i, const ros::Time& t) {
    graph.Publish(ImageMessage(sequence.images[i], t), InfoMessage(camera, t));
    return WaitFor([&] { return received.Has(received.geometry, StampText(t)); }, 20);
  };
  const ros::Time before(1700000000, 0);
  ASSERT_TRUE(send_and_wait(0, before)) << live.NodeLog();
  {
    std::lock_guard<std::mutex> lock(received.mutex);
    const auto& geometry = received.geometry[StampText(before)];
    EXPECT_EQ(Value(geometry, "status"), "failed");
    EXPECT_NE(Value(geometry, "note").find("base_footprint"), std::string::npos)
        << Value(geometry, "note");
    EXPECT_EQ(received.depth.count(StampKey(before)), 0u);
  }

  ros::NodeHandle nh;
  ros::Publisher tf = nh.advertise<tf2_msgs::TFMessage>("/tf_static", 1, /*latch=*/true);
  tf2_msgs::TFMessage transforms;
  geometry_msgs::TransformStamped mount;
  mount.header.stamp = before;
  mount.header.frame_id = "base_footprint";
  mount.child_frame_id = kFrameId;
  mount.transform.translation.x = 0.2;
  mount.transform.translation.z = camera.mount_height;
  // The optical frame (z forward, x right, y down) on a base whose x is forward and z up.
  mount.transform.rotation.x = -0.5;
  mount.transform.rotation.y = 0.5;
  mount.transform.rotation.z = -0.5;
  mount.transform.rotation.w = 0.5;
  transforms.transforms.push_back(mount);
  tf.publish(transforms);
  ASSERT_TRUE(WaitFor([&] { return tf.getNumSubscribers() > 0; }, 20));
  for (int i = 1; i < 3; ++i) {
    const ros::Time t = before + ros::Duration(0.1 * i);
    ASSERT_TRUE(send_and_wait(i, t)) << live.NodeLog();
    ASSERT_TRUE(WaitFor([&] { return received.Has(received.depth, StampKey(t)); }, 20))
        << "frame " << i << ": no depth\n"
        << live.NodeLog();
    std::lock_guard<std::mutex> lock(received.mutex);
    const auto& geometry = received.geometry[StampText(t)];
    EXPECT_EQ(Value(geometry, "status"), "ok");
    EXPECT_NEAR(std::atof(Value(geometry, "camera_height_m").c_str()), camera.mount_height, 1e-6);
    // A level camera: no roll found (the key is there, and near zero).
    ASSERT_FALSE(Value(geometry, "roll_rad").empty());
    EXPECT_LT(std::abs(std::atof(Value(geometry, "roll_rad").c_str())), 0.3 * M_PI / 180);
    // ~depth_encoding:=16UC1: millimetres, the truth's within 5% at the bottom centre (floor).
    const sensor_msgs::Image& depth = *received.depth[StampKey(t)];
    EXPECT_EQ(depth.encoding, "16UC1");
    ASSERT_EQ(depth.step, 2 * depth.width);
    const cv::Mat metres = DepthFromMessage(depth);
    const int row = camera.image_height - 10, col = camera.image_width / 2;
    const float truth = sequence.truth[i].at<float>(row, col);
    EXPECT_NEAR(metres.at<float>(row, col), truth, 0.05 * truth);
  }
  EXPECT_TRUE(live.NodeRunning());
}

// A bad parameter stops the node at start-up (exit 2) naming it; ~min_confidence is one of the
// options it reads.
TEST(NodeLiveTest, BadParameterNamedAtStartUp) {
  Scratch dir;
  g_deadline = Clock::now() + std::chrono::minutes(1);
  for (const auto& [arg, name] : std::vector<std::pair<std::string, std::string>>{
           {"_min_confidence:=1.5", "min_confidence"},
           {"_depth_encoding:=mono16", "depth_encoding"},
           {"_solver:=nonesuch", "nonesuch"}}) {
    LiveNode live(dir, {"_camera_height:=0.7", arg});
    ASSERT_TRUE(live.Start()) << "no ROS master:\n"
                              << Master::Get().Log();
    EXPECT_TRUE(WaitFor([&] { return !live.NodeRunning(); }, 20)) << arg;
    EXPECT_EQ(live.ExitCode(), 2) << arg;
    EXPECT_NE(live.NodeLog().find(name), std::string::npos) << arg << ": " << live.NodeLog();
  }
}

}  // namespace
}  // namespace testing_util
}  // namespace corridor
