#include "tools/input_source.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "corridor_depth/evaluation.h"
#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/image_io.h"
#ifdef CORRIDOR_HAVE_ROSBAG
#include "io/rosbag_io.h"
#endif
#include "tools/focal_auto.h"
#include "tools/frame_source.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;

// The extension with its dot, lower-cased: "a/B.BAG" -> ".bag".
std::string LowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool Exists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

// The folder's own name, also for "." and trailing slashes.
std::string FolderName(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(dir, ec);
  if (ec) p = dir.lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  return p.filename().string();
}

// A pinhole from --fx/--fy/--cx/--cy or --hfov, sized by the scene's first image.
Status CameraFromFlags(const CameraOverrides& o, InputScene* scene) {
  if (scene->kind == InputKind::kImages && scene->frames.empty()) {
    return Status::InvalidArgument("no image to size the camera by");
  }
  // --hfov alone on images: each image is read upright and gets a camera of its own size.
  const bool per_image = o.fx <= 0 && o.focal != "auto" && scene->kind == InputKind::kImages;
  if (per_image) scene->per_image_hfov_deg = o.hfov_deg;
  cv::Mat first;
  const Status status = ReadFirstFrame(*scene, &first);
  if (!status.ok()) return status;
  if (o.fx > 0) {
    scene->camera.image_width = first.cols;
    scene->camera.image_height = first.rows;
    scene->camera.fx = o.fx;
    scene->camera.fy = o.fy > 0 ? o.fy : o.fx;
    scene->camera.cx = o.cx >= 0 ? o.cx : 0.5 * (first.cols - 1);
    scene->camera.cy = o.cy >= 0 ? o.cy : 0.5 * (first.rows - 1);
    scene->camera_source = "--fx/--fy/--cx/--cy";
  } else if (o.focal == "auto") {
    const double fallback = o.hfov_deg > 0 ? o.hfov_deg : kDefaultFallbackHfovDeg;
    double focal = 0;
    const Status estimated = EstimateSceneFocal(*scene, fallback, &focal, &scene->camera_source);
    if (!estimated.ok()) return estimated;
    scene->camera = Camera::FromHorizontalFov(first.cols, first.rows, M_PI / 2, 0);
    scene->camera.fx = scene->camera.fy = focal;
  } else {
    scene->camera = Camera::FromHorizontalFov(first.cols, first.rows, o.hfov_deg * M_PI / 180.0, 0);
    scene->camera_source = "--hfov";
  }
  return Status::Ok();
}

// Applies the overrides and checks the camera; `found` is the YAML that applies ("" if none).
Status FinishCamera(const CameraOverrides& overrides, const std::string& found,
                    const std::string& scene_path, InputScene* scene) {
  if (!overrides.focal.empty() && overrides.focal != "auto") {
    return Status::InvalidArgument("--focal=" + overrides.focal + ": the only value is 'auto'");
  }
  if (overrides.focal == "auto" && (!overrides.camera_file.empty() || overrides.fx > 0)) {
    return Status::InvalidArgument(
        "--focal=auto estimates the focal length: it does not go with "
        "--camera or --fx");
  }
  const bool pinhole_flags = overrides.camera_file.empty() && overrides.fx > 0;
  const bool fov_flag = overrides.camera_file.empty() &&
                        ((found.empty() && overrides.hfov_deg > 0) || overrides.focal == "auto");
  if (pinhole_flags || fov_flag) {
    if (!(overrides.hfov_deg >= 0 && overrides.hfov_deg < 180)) {
      return Status::InvalidArgument("--hfov must be in (0, 180) degrees");
    }
    Status status = CameraFromFlags(overrides, scene);
    if (!status.ok()) return status;
    if (overrides.camera_height != 0) {
      scene->camera.mount_height = overrides.camera_height;
    } else if (!found.empty()) {  // --focal=auto beside a camera.yaml: its camera_height.
      Camera beside;
      if (ReadCameraYaml(found, &beside).ok()) scene->camera.mount_height = beside.mount_height;
    }
    if (scene->camera.mount_height == 0) {
      return Status::InvalidArgument("camera height unknown for " + scene_path + ": pass --camera_height=M");
    }
    std::string why;
    if (!scene->camera.Check(&why)) return Status::InvalidArgument(scene->camera_source + ": " + why);
    return Status::Ok();
  }
  const std::string path = overrides.camera_file.empty() ? found : overrides.camera_file;
  if (path.empty()) {
    return Status::InvalidArgument(
        "no camera calibration for " + scene_path +
        ": pass --camera=FILE, --fx (with --fy, --cx, --cy) or --hfov=DEG, or put a camera.yaml "
        "beside the images");
  }
  if (!overrides.camera_file.empty() || scene->camera_source != path) {
    const Status status = ReadCameraYaml(path, &scene->camera);
    if (!status.ok()) return status;
  }
  scene->camera_source = path;
  if (overrides.camera_height != 0) scene->camera.mount_height = overrides.camera_height;
  if (scene->camera.mount_height == 0) {  // Negative or non-finite: Check below names it.
    return Status::InvalidArgument("camera height unknown for " + scene_path +
                                   ": pass --camera_height=M or add camera_height to " + path);
  }
  std::string why;
  if (!scene->camera.Check(&why)) {  // Names the flag when its height is what is wrong.
    const bool bad_flag = overrides.camera_height != 0 && scene->camera.CheckIntrinsics(nullptr);
    return Status::InvalidArgument((bad_flag ? std::string("--camera_height") : path) + ": " + why);
  }
  return Status::Ok();
}

// camera.yaml beside the images, then one folder up; "" when neither exists.
std::string NearbyCamera(const fs::path& folder) {
  for (const fs::path& candidate : {folder / "camera.yaml", folder.parent_path() / "camera.yaml"}) {
    if (Exists(candidate)) return candidate.string();
  }
  return "";
}

DatasetFrame FrameFromImage(const fs::path& image) {
  DatasetFrame frame;
  frame.name = image.stem().string();
  frame.rgb_path = image.string();
  return frame;
}

// The flags that give a camera without a file beside the input: --camera, --fx, --hfov.
bool CameraFromCommandLine(const CameraOverrides& o) {
  return !o.camera_file.empty() || o.fx > 0 || o.hfov_deg > 0 || o.focal == "auto";
}

// A ROS 1 bag: one scene named by the bag, its camera from the bag's CameraInfo unless the
// command line gives one.
Status ResolveBag(const std::string& input, const CameraOverrides& overrides,
                  const BagTopicOptions& topics, InputScene* scene) {
  scene->kind = InputKind::kRosBag;
  scene->stream_path = input;
  scene->name = fs::path(input).stem().string();
#ifdef CORRIDOR_HAVE_ROSBAG
  std::string info_topic;
  uint32_t messages = 0;
  Status status = ChooseBagTopics(input, topics.image_topic, topics.camera_info_topic,
                                  &scene->image_topic, &info_topic, &messages);
  if (!status.ok()) return status;
  scene->frame_count = messages;
  const std::string where = input + " " + scene->image_topic;
  if (CameraFromCommandLine(overrides)) return FinishCamera(overrides, "", where, scene);
  if (info_topic.empty()) {
    return Status::InvalidArgument(input + ": no sensor_msgs/CameraInfo beside " +
                                   scene->image_topic +
                                   " and no --camera; pass --camera=FILE, --camera_info_topic, "
                                   "or --fx/--hfov");
  }
  status = ReadBagCameraInfo(input, info_topic, &scene->camera, &scene->frame_id);
  if (!status.ok()) return status;
  scene->camera_source = input + " " + info_topic;
  scene->camera.mount_height = overrides.camera_height;
  if (overrides.camera_height == 0) {
    return Status::InvalidArgument("camera height unknown for " + where +
                                   " (CameraInfo has none): pass --camera_height=M");
  }
  std::string why;
  if (!scene->camera.Check(&why)) return Status::InvalidArgument("--camera_height: " + why);
  return Status::Ok();
#else
  (void)overrides;
  (void)topics;
  return Status::InvalidArgument(input +
                                 ": this build has no ROS bag support (configure with "
                                 "-DCORRIDOR_WITH_ROSBAG=ON)");
#endif
}

// A video: one scene named by the file; the camera must come from the command line.
Status ResolveVideo(const std::string& input, const CameraOverrides& overrides,
                    InputScene* scene) {
  scene->kind = InputKind::kVideo;
  scene->stream_path = input;
  scene->name = fs::path(input).stem().string();
  if (!CameraFromCommandLine(overrides)) {
    return Status::InvalidArgument(input +
                                   ": a video carries no calibration; pass --camera=FILE "
                                   "(or --fx/--fy/--cx/--cy, or --hfov=DEG) and --camera_height=M");
  }
  cv::Mat first;
  Status status = ReadFirstFrame(*scene, &first);  // Opens it: a clear error if it cannot.
  if (!status.ok()) return status;
  std::unique_ptr<cv::VideoCapture> capture;
  status = OpenVideo(input, &capture);
  if (!status.ok()) return status;
  const double count = capture->get(cv::CAP_PROP_FRAME_COUNT);
  const double fps = capture->get(cv::CAP_PROP_FPS);
  scene->frame_count = count > 0 && std::isfinite(count) ? static_cast<int64_t>(count) : 0;
  if (fps > 0 && std::isfinite(fps)) scene->frame_period = 1.0 / fps;
  return FinishCamera(overrides, "", input, scene);
}

}  // namespace

bool IsVideoPath(const std::string& path) {
  static const char* const kVideo[] = {".avi", ".mp4", ".mkv", ".mov", ".webm", ".m4v",
                                       ".mpg", ".mpeg", ".wmv", ".flv", ".ogv", ".mjpeg"};
  const std::string ext = LowerExtension(path);
  for (const char* v : kVideo) {
    if (ext == v) return true;
  }
  return false;
}

Status ResolveInput(const std::string& input, const CameraOverrides& overrides,
                    std::vector<InputScene>* scenes, const BagTopicOptions& bag_topics) {
  scenes->clear();
  if (input.empty()) return Status::InvalidArgument("--input is required");
  const fs::path path(input);
  if (!Exists(path)) return Status::NotFound(input + ": no such file or folder");
  std::error_code ec;
  if (!fs::is_directory(path, ec) && (LowerExtension(input) == ".bag" || IsVideoPath(input))) {
    InputScene scene;
    const Status status = LowerExtension(input) == ".bag"
                              ? ResolveBag(input, overrides, bag_topics, &scene)
                              : ResolveVideo(input, overrides, &scene);
    if (!status.ok()) return status;
    scenes->push_back(std::move(scene));
    return Status::Ok();
  }
  if (!fs::is_directory(path, ec)) {
    // A single image: the scene is its folder (or the scene above an rgb/ folder).
    fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    InputScene scene;
    scene.name = FolderName(folder) == "rgb" ? FolderName(folder.parent_path()) : FolderName(folder);
    scene.frames.push_back(FrameFromImage(path));
    const Status status = FinishCamera(overrides, NearbyCamera(folder), input, &scene);
    if (!status.ok()) return status;
    scenes->push_back(std::move(scene));
    return Status::Ok();
  }
  if (IsDatasetRoot(input)) {
    std::vector<DatasetScene> dataset;
    Status status = LoadDataset(input, &dataset);
    if (!status.ok()) return status;
    for (auto& d : dataset) {
      InputScene scene;
      scene.name = d.name;
      scene.camera = d.camera;
      scene.camera_source = d.camera_path;
      scene.frames = std::move(d.frames);
      status = FinishCamera(overrides, d.camera_path, d.dir, &scene);
      if (!status.ok()) return status;
      scenes->push_back(std::move(scene));
    }
    return Status::Ok();
  }
  std::vector<std::string> images;
  Status status = ListImages(input, &images);
  if (!status.ok()) return status;
  InputScene scene;
  scene.name = FolderName(path);
  for (const auto& image : images) scene.frames.push_back(FrameFromImage(image));
  status = FinishCamera(overrides, NearbyCamera(path), input, &scene);
  if (!status.ok()) return status;
  scenes->push_back(std::move(scene));
  return Status::Ok();
}

Camera FrameCamera(const InputScene& scene, const cv::Size& image_size) {
  return PerImageCamera(scene.camera, scene.per_image_hfov_deg, image_size);
}

Status CheckFirstFrameSize(const InputScene& scene) {
  if (scene.kind == InputKind::kImages && scene.frames.empty()) return Status::Ok();
  if (scene.per_image_hfov_deg > 0) return Status::Ok();  // Each image has a camera of its size.
  const bool stream = scene.kind != InputKind::kImages;
  const std::string path = stream ? scene.stream_path : scene.frames.front().rgb_path;
  cv::Mat image;
  const Status read = ReadFirstFrame(scene, &image);
  // A bag or video whose first frame does not decode (an unsupported encoding) is a
  // configuration error; one bad image file among many is a failed frame.
  if (!read.ok()) return stream ? read : Status::Ok();
  const Camera& camera = scene.camera;
  if (image.cols == camera.image_width && image.rows == camera.image_height) return Status::Ok();
  return Status::InvalidArgument(
      "image " + path + " is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
      " but the calibration " + scene.camera_source + " is for " +
      std::to_string(camera.image_width) + "x" + std::to_string(camera.image_height) +
      "; pass the camera of these images with --camera=FILE");
}

}  // namespace corridor
