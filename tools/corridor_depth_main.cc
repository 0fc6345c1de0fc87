// corridor_depth: dense metric depth from corridor images.
//   corridor_depth --input=PATH --output_dir=DIR [--camera=FILE] [--camera_height=M]
//                  [--solver=NAME] [--rasterizer=NAME] [--skip_existing]
//                  [--image_topic=T] [--camera_info_topic=T] [--write_cloud] [--output_bag=FILE]
// PATH is an image, a folder of images, a dataset root, a ROS 1 bag or a video. Writes, per
// scene, DIR/<scene>/depth/<frame>.png (16-bit mm, 0 = none), DIR/<scene>/vis/<frame>.png and
// DIR/<scene>/geometry.csv; bag frames are named <sec>.<nsec>, video frames by their index.
// Exit code 0: all frames ok; 1: some frames failed; 2: bad usage or configuration (also a camera
// whose size is not the first image's, a bag topic that is not there, an unsupported encoding).

#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "depth/point_cloud.h"
#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/image_io.h"
#include "corridor_depth/ply_io.h"
#ifdef CORRIDOR_HAVE_ROSBAG
#include "io/rosbag_io.h"
#endif
#include "pipeline/confidence_mask.h"
#include "pipeline/floor_mask.h"
#include "pipeline/frame_pipeline.h"
#include "pipeline/image_input.h"
#include "corridor_depth/recover_depth.h"
#include "corridor_depth/visualization.h"
#include "tools/frame_source.h"
#include "tools/geometry_csv.h"
#include "tools/input_source.h"
#include "tools/progress.h"
#include "tools/tool_flags.h"
#include "tools/tool_help.h"

DEFINE_string(input, "", "An image, a folder of images, a dataset root, a ROS 1 bag or a video");
DEFINE_string(output_dir, "", "Where the depth maps, pictures and geometry.csv go");
DEFINE_bool(write_vis, true, "Write DIR/<scene>/vis/<frame>.png (input with lines beside depth)");
DEFINE_double(vis_max_depth, 15.0, "Depth at the top of the colour scale in vis/, m");
DEFINE_bool(write_floor_mask, false,
            "Write DIR/<scene>/floor/<frame>.png: the floor the geometry predicts (255 = floor)");
DEFINE_bool(write_model_fit, false,
            "Write DIR/<scene>/model_fit/<frame>.png: 255 where the box model explains the image's "
            "pixels (a per-pixel mask; not the frame's confidence, which geometry.csv gives)");
DEFINE_bool(write_confidence, false, "Old name of --write_model_fit");
DEFINE_bool(skip_existing, false,
            "Resume: skip frames whose depth PNG and geometry.csv row are already in the output");
DEFINE_string(image_topic, "",
              "ROS bag input: the sensor_msgs/Image or CompressedImage topic (default: the only one)");
DEFINE_string(camera_info_topic, "",
              "ROS bag input: the CameraInfo topic (default: camera_info beside the image topic)");
DEFINE_bool(write_cloud, false,
            "Write DIR/<scene>/cloud/<frame>.ply: binary PLY, x y z (camera frame, m) + colour");
DEFINE_string(output_bag, "",
              "Write the depth maps to this ROS 1 bag: <prefix>/depth/image plus CameraInfo on "
              "<prefix>/depth/camera_info, at the input stamps (frames without a stamp: 1 s + "
              "index x frame period), as the live node corridor_depth_node publishes them");
DEFINE_string(output_bag_prefix, "",
              "--output_bag's topic namespace (default: the image topic's parent without a "
              "transport suffix, /cam/image_raw/compressed -> /cam; /<scene> for other inputs)");
DEFINE_string(depth_encoding, "32FC1",
              "--output_bag's depth encoding: 32FC1 (metres, NaN = none) or 16UC1 (mm, 0 = none)");

namespace corridor {
namespace {

namespace fs = std::filesystem;

int Usage(const std::string& message) {
  std::fprintf(stderr, "corridor_depth: %s\n", message.c_str());
  return 2;
}

// The "<sec>.<nsec>" of a stamped frame, "" otherwise.
std::string StampText(const PipelineFrame& frame) {
#ifdef CORRIDOR_HAVE_ROSBAG
  if (frame.stamp_ns >= 0) return BagStamp::FromNanoseconds(frame.stamp_ns).ToString();
#endif
  (void)frame;
  return "";
}

// Writes one frame's outputs and its geometry row; `rays` is set with --write_cloud.
Status WriteFrame(const fs::path& scene_dir, const PipelineFrame& frame, const RayTable* rays,
                  GeometryCsv* csv) {
  const RecoverDepthResult& result = frame.result;
  csv->Add(frame.name, result, StampText(frame));
  if (!result.depth.empty()) {
    const Status status =
        WriteDepthPng((scene_dir / "depth" / (frame.name + ".png")).string(), result.depth);
    if (!status.ok()) return status;
    if (rays != nullptr) {
      PointCloud cloud;
      Status built = DepthToPointCloud(*rays, result.depth, frame.image, &cloud);
      if (built.ok()) {
        built = WritePlyAtomic((scene_dir / "cloud" / (frame.name + ".ply")).string(), cloud);
      }
      if (!built.ok()) return built;
    }
    if (FLAGS_write_floor_mask) {
      const Status written =
          WriteImageAtomic((scene_dir / "floor" / (frame.name + ".png")).string(),
                           PredictFloorMask(*frame.camera, result.geometry, FLAGS_max_range));
      if (!written.ok()) return written;
    }
    cv::Mat bgr;
    if (FLAGS_write_model_fit && ToBgr(frame.image, *frame.camera, &bgr).ok()) {
      const Status written = WriteImageAtomic(
          (scene_dir / "model_fit" / (frame.name + ".png")).string(),
          ComputeConfidenceMask(bgr, result.depth, *frame.camera, result.geometry));
      if (!written.ok()) return written;
    }
  }
  if (FLAGS_write_vis && !frame.image.empty()) {
    return WriteImageAtomic((scene_dir / "vis" / (frame.name + ".png")).string(),
                            MakeResultPanel(frame.image, result, FLAGS_vis_max_depth));
  }
  return Status::Ok();
}

// The geometry.csv rows an earlier run wrote into the scene's folder, by frame name and in file
// order (migrated from an older header), so that a second run keeps them: a frame computed again
// replaces its own row. With --skip_existing, *kept holds the rows of the frames whose depth PNG
// is there too, which are not computed again. An unreadable or foreign geometry.csv stops the run
// before anything is written (it is never overwritten).
Status EarlierRows(const fs::path& scene_dir, std::map<std::string, std::string>* earlier,
                   std::vector<std::string>* order, std::map<std::string, std::string>* kept) {
  kept->clear();
  const Status status = ReadGeometryCsvRows((scene_dir / "geometry.csv").string(), earlier, order);
  if (status.code() == StatusCode::kNotFound) return Status::Ok();
  if (!status.ok()) return status;
  if (!FLAGS_skip_existing) return Status::Ok();
  for (const auto& [name, row] : *earlier) {
    std::error_code ec;
    if (fs::exists(scene_dir / "depth" / (name + ".png"), ec)) (*kept)[name] = row;
  }
  return Status::Ok();
}

// --output_bag: where a scene's depth goes in the bag.
struct BagOutput {
#ifdef CORRIDOR_HAVE_ROSBAG
  BagDepthWriter* writer = nullptr;  // The open output bag; null without --output_bag.
#endif
  std::string depth_topic;  // <prefix>/depth/image.
  std::string info_topic;   // <prefix>/depth/camera_info.
  std::string frame_id;     // The input's CameraInfo frame_id, else "camera".
};

// Writes one frame's depth to the output bag, at its stamp or at 1 s + position x frame period.
Status WriteToBag(const BagOutput& bag, const InputScene& scene, const PipelineFrame& frame,
                  size_t position) {
#ifdef CORRIDOR_HAVE_ROSBAG
  if (bag.writer == nullptr || frame.result.depth.empty()) return Status::Ok();
  const int64_t ns = frame.stamp_ns >= 0
                         ? frame.stamp_ns
                         : 1000000000LL + static_cast<int64_t>(std::llround(
                                              1e9 * scene.frame_period * static_cast<double>(position)));
  return bag.writer->Write(bag.depth_topic, bag.info_topic, BagStamp::FromNanoseconds(ns),
                           bag.frame_id, frame.result.depth, *frame.camera);
#else
  (void)bag, (void)scene, (void)frame, (void)position;
  return Status::Ok();
#endif
}

// Processes one scene through the two-thread pipeline; returns the number of failed frames, or
// -1 when the input cannot be opened or an output cannot be written (which stops the run:
// nothing more could be saved). *frames counts the scene's frames, *skipped the kept ones.
int RunScene(const InputScene& scene, const DepthRecoverer& recoverer, const std::string& out,
             const BagOutput& bag, int* frames, int* skipped) {
  const fs::path scene_dir = fs::path(out) / scene.name;
  const std::string csv_path = (scene_dir / "geometry.csv").string();
  std::map<std::string, std::string> earlier, kept;
  std::vector<std::string> earlier_order;
  Status write_error = EarlierRows(scene_dir, &earlier, &earlier_order, &kept);
  // The camera that was used (from a file, a bag, or --fx/--hfov), so that every run records it.
  if (write_error.ok()) {
    write_error = WriteCameraYaml((scene_dir / "camera_used.yaml").string(), scene.camera);
  }
  if (!write_error.ok()) {
    LOG(ERROR) << "corridor_depth: " << write_error.ToString();
    return -1;
  }
  std::unique_ptr<FrameSource> input;
  const Status opened = OpenFrameSource(scene, &input);
  if (!opened.ok()) {
    LOG(ERROR) << "corridor_depth: " << opened.ToString();
    return -1;
  }
  std::unique_ptr<RayTable> rays;
  if (FLAGS_write_cloud) rays = std::make_unique<RayTable>(scene.camera);
  const int64_t known = scene.kind == InputKind::kImages
                            ? static_cast<int64_t>(scene.frames.size())
                            : scene.frame_count;
  const int total = static_cast<int>(std::max<int64_t>(0, known - static_cast<int64_t>(kept.size())));
  // This run's geometry.csv rows in input order ("" = not done yet) with their frame names, and
  // each computed frame's position in them; the source (extraction thread) appends, the sink
  // (this thread) fills. The earlier run's rows come first, each replaced by this run's when the
  // frame was computed again; this run's other frames follow in input order.
  std::mutex mutex;
  std::vector<std::string> rows, row_names;
  std::vector<size_t> position_of;
  const auto write_csv = [&]() {
    GeometryCsv csv;
    std::lock_guard<std::mutex> lock(mutex);
    std::map<std::string, const std::string*> now;
    for (size_t i = 0; i < rows.size(); ++i) {
      if (!rows[i].empty()) now[row_names[i]] = &rows[i];
    }
    for (const auto& name : earlier_order) {
      const auto found = now.find(name);
      csv.AddRow(found != now.end() ? *found->second : earlier.at(name));
      if (found != now.end()) now.erase(found);
    }
    for (size_t i = 0; i < rows.size(); ++i) {
      if (now.count(row_names[i]) != 0) csv.AddRow(rows[i]);
    }
    return WriteTextAtomic(csv_path, csv.Text());
  };
  Progress progress(scene.name, total);
  int failed = 0;
  const auto source = [&](PipelineFrame* frame) {
    for (;;) {
      PipelineFrame next;
      if (!input->Next(&next)) return false;
      std::lock_guard<std::mutex> lock(mutex);
      const auto row = kept.find(next.name);
      if (row != kept.end()) {
        rows.push_back(row->second);
        row_names.push_back(next.name);
        ++*skipped;
        continue;
      }
      position_of.push_back(rows.size());
      rows.emplace_back();
      row_names.push_back(next.name);
      if (scene.per_image_hfov_deg > 0 && !next.image.empty()) {
        next.owned_camera = std::make_shared<Camera>(FrameCamera(scene, next.image.size()));
        next.camera = next.owned_camera.get();
      } else {
        next.camera = &scene.camera;
      }
      *frame = std::move(next);
      return true;
    }
  };
  const auto sink = [&](PipelineFrame&& frame) {
    size_t position;
    {
      std::lock_guard<std::mutex> lock(mutex);
      position = position_of[static_cast<size_t>(frame.index)];
    }
    if (!frame.result.status.ok()) {
      ++failed;
      const std::string where = scene.kind == InputKind::kImages
                                    ? scene.frames[position].rgb_path
                                    : scene.stream_path + " frame " + frame.name;
      progress.Break();
      LOG(WARNING) << "frame " << where << " failed: " << frame.result.status.ToString();
    }
    if (VLOG_IS_ON(1)) {
      const CorridorGeometry& g = frame.result.geometry;
      LOG(INFO) << scene.name << "/" << frame.name << ": " << frame.result.status.ToString();
      if (frame.result.has_geometry) {
        LOG(INFO) << "  yaw " << g.yaw << " rad, pitch " << g.pitch << " rad, offset " << g.offset
                  << " m, width " << g.width << " m, ceiling " << g.ceiling_height << " m";
      }
    }
    GeometryCsv row;
    write_error = WriteFrame(scene_dir, frame, rays.get(), &row);
    if (write_error.ok()) write_error = WriteToBag(bag, scene, frame, position);
    {
      std::lock_guard<std::mutex> lock(mutex);
      rows[position] = row.rows().front();
    }
    if (write_error.ok() && (frame.index + 1) % 50 == 0) write_error = write_csv();
    progress.Tick(static_cast<int>(frame.index + 1));
    return write_error.ok();
  };
  bool sequence = false;
  const Status resolved = ResolveSequence(scene.kind != InputKind::kImages, &sequence);
  if (!resolved.ok()) {
    std::fprintf(stderr, "corridor_depth: %s\n", resolved.message().c_str());
    return -1;
  }
  const int64_t computed = FramePipeline(recoverer, 4, sequence).Run(source, sink);
  progress.Finish();
  if (write_error.ok()) write_error = write_csv();  // Every row, the kept ones included.
  if (!write_error.ok()) {
    LOG(ERROR) << "corridor_depth: cannot write output: " << write_error.ToString();
    return -1;
  }
  *frames = static_cast<int>(computed) + *skipped;
  return failed;
}

ToolInfo DepthToolInfo() {
  ToolInfo info;
  info.name = "corridor_depth";
  info.summary = "dense metric depth from images of a corridor";
  info.usage =
      "corridor_depth --input=photo.jpg --hfov=60 --camera_height=1.2 --output_dir=out\n"
      "corridor_depth --input=PATH --camera=camera.yaml --output_dir=DIR [--solver=NAME]\n"
      "corridor_depth --input=run.bag --image_topic=T --camera_height=M --output_dir=DIR";
  info.notes =
      "--input is an image, a folder of images, a dataset root, a ROS 1 bag or a video. Writes, "
      "per scene, DIR/<scene>/depth/<frame>.png (16-bit millimetres, 0 = no estimate), "
      "DIR/<scene>/vis/<frame>.png and DIR/<scene>/geometry.csv. Exit code 0: every frame ok; "
      "1: some frames without depth; 2: bad usage, found before any work.";
  info.flag_files = {"corridor_depth_main.cc", "tool_flags.cc"};
  info.aliases = {{"write_confidence", "write_model_fit"}};
  return info;
}

int Main(int argc, char** argv) {
  RewriteBareSequenceFlag(argc, argv);
  int exit_code = 0;
  if (!ParseToolFlags(DepthToolInfo(), &argc, &argv, &exit_code)) return exit_code;
  if (argc > 1) return Usage(std::string("unexpected argument '") + argv[1] + "'");
  if (FLAGS_input.empty()) {
    return Usage("--input is required (an image, a folder, a dataset, a ROS bag or a video)");
  }
  if (FLAGS_output_dir.empty()) return Usage("--output_dir is required");
  if (!(FLAGS_vis_max_depth > 0)) return Usage("--vis_max_depth must be positive");
  {
    bool sequence = false;
    const Status valid = ResolveSequence(false, &sequence);
    if (!valid.ok()) return Usage(valid.message());
  }
  if (!FLAGS_output_bag.empty() && FLAGS_skip_existing) {
    return Usage(
        "--output_bag and --skip_existing do not go together: the kept frames would be "
        "missing from the new bag");
  }
#ifndef CORRIDOR_HAVE_ROSBAG
  if (!FLAGS_output_bag.empty()) {
    return Usage(
        "--output_bag: this build has no ROS bag support (configure with "
        "-DCORRIDOR_WITH_ROSBAG=ON)");
  }
#endif

  RecoverDepthOptions options;
  Status status = RecoverDepthOptionsFromFlags(&options);
  if (!status.ok()) return Usage(status.message());
  std::unique_ptr<DepthRecoverer> recoverer;
  status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) return Usage(status.message());
  std::vector<InputScene> scenes;
  BagTopicOptions topics;
  topics.image_topic = FLAGS_image_topic;
  topics.camera_info_topic = FLAGS_camera_info_topic;
  status = ResolveInput(FLAGS_input, CameraOverridesFromFlags(), &scenes, topics);
  if (!status.ok()) return Usage(status.message());
  if (FLAGS_focal == "auto") {
    for (const auto& scene : scenes) {
      std::printf("%s: scene %s: %s\n", "corridor_depth", scene.name.c_str(), scene.camera_source.c_str());
    }
  }
  for (const auto& scene : scenes) {
    status = CheckFirstFrameSize(scene);
    if (!status.ok()) return Usage(status.message());
  }

#ifdef CORRIDOR_HAVE_ROSBAG
  std::unique_ptr<BagDepthWriter> bag_writer;
  if (!FLAGS_output_bag.empty()) {
    status = BagDepthWriter::Open(FLAGS_output_bag, &bag_writer, FLAGS_depth_encoding);
    if (!status.ok()) return Usage(status.message());
  }
#endif
  int failed = 0, total = 0, skipped = 0;
  for (const auto& scene : scenes) {
    BagOutput bag;
#ifdef CORRIDOR_HAVE_ROSBAG
    bag.writer = bag_writer.get();
#endif
    std::string prefix = FLAGS_output_bag_prefix;
#ifdef CORRIDOR_HAVE_ROSBAG
    if (prefix.empty()) {
      prefix = scene.image_topic.empty() ? "/" + scene.name : DepthTopicPrefix(scene.image_topic);
    }
#endif
    if (!prefix.empty() && prefix.back() == '/') prefix.pop_back();
    bag.depth_topic = prefix + "/depth/image";
    bag.info_topic = prefix + "/depth/camera_info";
    bag.frame_id = scene.frame_id.empty() ? "camera" : scene.frame_id;
    int scene_frames = 0, scene_skipped = 0;
    const int scene_failed =
        RunScene(scene, *recoverer, FLAGS_output_dir, bag, &scene_frames, &scene_skipped);
    if (scene_failed < 0) return 2;
    failed += scene_failed;
    skipped += scene_skipped;
    total += scene_frames;
  }
#ifdef CORRIDOR_HAVE_ROSBAG
  if (bag_writer) {
    status = bag_writer->Close();
    if (!status.ok()) {
      LOG(ERROR) << "corridor_depth: " << status.ToString();
      return 2;
    }
  }
#endif
  std::printf(
      "corridor_depth: %d of %d frames ok, %d of them kept from an earlier run "
      "(solver %s, rasterizer %s); outputs in %s%s%s\n",
      total - failed, total, skipped, options.solver.c_str(), options.rasterizer.c_str(),
      FLAGS_output_dir.c_str(), FLAGS_output_bag.empty() ? "" : ", depth bag ",
      FLAGS_output_bag.c_str());
  return failed > 0 ? 1 : 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
