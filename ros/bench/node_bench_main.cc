// corridor_node_bench: feeds a generated corridor sequence to a running corridor_depth_node and
// measures it. ROS_MASTER_URI must point at the node's master.
//   corridor_node_bench DATASET_SCENE_DIR [RATE_HZ] [PASSES] [NAMESPACE]
// RATE_HZ 0 (default): lockstep, each frame after the previous depth came back (the node's
// throughput); > 0: a free-running camera at that rate (the newest-frame mailbox drops the rest).
// Prints the latency from image stamp to depth arrival here (median, p99), the node's own
// latency to publication from /diagnostics, depth frames per second and the frames dropped.

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <opencv2/imgcodecs.hpp>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "corridor_depth/camera_yaml.h"

namespace {

double Quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t rank = static_cast<size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: corridor_node_bench SCENE_DIR [RATE_HZ] [PASSES] [NAMESPACE]\n");
    return 2;
  }
  const std::string scene = argv[1];
  const double rate = argc > 2 ? std::atof(argv[2]) : 0.0;
  const int passes = argc > 3 ? std::atoi(argv[3]) : 1;
  const std::string ns = argc > 4 ? argv[4] : "/cd";
  corridor::Camera camera;
  if (!corridor::ReadCameraYaml(scene + "/camera.yaml", &camera).ok()) return 2;
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(scene + "/rgb")) {
    files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<sensor_msgs::Image> images;
  for (const auto& f : files) {
    const cv::Mat bgr = cv::imread(f, cv::IMREAD_COLOR);
    sensor_msgs::Image m;
    m.header.frame_id = "cam_optical";
    m.height = static_cast<uint32_t>(bgr.rows);
    m.width = static_cast<uint32_t>(bgr.cols);
    m.encoding = "bgr8";
    m.step = m.width * 3;
    m.data.assign(bgr.data, bgr.data + bgr.total() * 3);
    images.push_back(m);
  }
  int zero = 0;
  ros::init(zero, nullptr, "corridor_node_bench", ros::init_options::AnonymousName);
  ros::NodeHandle nh;
  ros::Publisher image_pub = nh.advertise<sensor_msgs::Image>("/cam/image_raw", 5);
  ros::Publisher info_pub = nh.advertise<sensor_msgs::CameraInfo>("/cam/camera_info", 5);
  std::mutex mutex;
  std::vector<double> latencies;
  std::atomic<int64_t> last_stamp{0};
  std::map<std::string, std::string> diagnostics;
  ros::Subscriber depth_sub = nh.subscribe<sensor_msgs::Image>(
      ns + "/depth/image", 10, [&](const sensor_msgs::ImageConstPtr& m) {
        const double latency = (ros::Time::now() - m->header.stamp).toSec();
        std::lock_guard<std::mutex> lock(mutex);
        latencies.push_back(latency);
        last_stamp = static_cast<int64_t>(m->header.stamp.toNSec());
      });
  ros::Subscriber diag_sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArrayConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& s : m->status) {
          if (s.name.find("corridor_depth") == std::string::npos) continue;
          for (const auto& kv : s.values) diagnostics[kv.key] = kv.value;
        }
      });
  ros::AsyncSpinner spinner(1);
  spinner.start();
  while (ros::ok() && (image_pub.getNumSubscribers() == 0 || depth_sub.getNumPublishers() == 0)) {
    ros::WallDuration(0.05).sleep();
  }
  sensor_msgs::CameraInfo info;
  info.header.frame_id = "cam_optical";
  info.width = static_cast<uint32_t>(camera.image_width);
  info.height = static_cast<uint32_t>(camera.image_height);
  info.distortion_model = "plumb_bob";
  info.D = {0, 0, 0, 0, 0};
  info.K = {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {camera.fx, 0, camera.cx, 0, 0, camera.fy, camera.cy, 0, 0, 0, 1, 0};
  const ros::WallTime start = ros::WallTime::now();
  int sent = 0;
  for (int pass = 0; pass < passes && ros::ok(); ++pass) {
    for (auto& image : images) {
      const ros::Time stamp = ros::Time::now();
      image.header.stamp = info.header.stamp = stamp;
      info_pub.publish(info);
      image_pub.publish(image);
      ++sent;
      if (rate > 0) {
        ros::WallDuration(1.0 / rate).sleep();
      } else {
        const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(10.0);
        while (last_stamp.load() != static_cast<int64_t>(stamp.toNSec()) &&
               ros::WallTime::now() < give_up) {
          std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
      }
    }
  }
  ros::WallDuration(1.0).sleep();  // The last depth and a diagnostics report.
  const double elapsed = (ros::WallTime::now() - start).toSec() - 1.0;
  ros::WallDuration(1.5).sleep();
  std::lock_guard<std::mutex> lock(mutex);
  std::printf("sent %d frames in %.2f s (%s), depth back for %zu: %.2f frames/s\n", sent, elapsed,
              rate > 0 ? "free-running" : "lockstep", latencies.size(),
              static_cast<double>(latencies.size()) / elapsed);
  std::printf("latency stamp -> depth received here: median %.1f ms, p99 %.1f ms\n",
              1e3 * Quantile(latencies, 0.5), 1e3 * Quantile(latencies, 0.99));
  std::printf(
      "node /diagnostics: latency to publication median %s s, p99 %s s; received %s, "
      "published %s, dropped %s\n",
      diagnostics["latency_median_s"].c_str(), diagnostics["latency_p99_s"].c_str(),
      diagnostics["frames_received"].c_str(), diagnostics["frames_published"].c_str(),
      diagnostics["frames_dropped"].c_str());
  return 0;
}
