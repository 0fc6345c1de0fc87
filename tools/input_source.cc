#include "tools/input_source.h"

#include <cmath>
#include <filesystem>
#include <system_error>

#include <opencv2/core.hpp>

#include "io/camera_yaml.h"
#include "io/image_io.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;

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
  if (scene->frames.empty()) return Status::InvalidArgument("no image to size the camera by");
  cv::Mat first;
  const Status status = ReadColorImage(scene->frames.front().rgb_path, &first);
  if (!status.ok()) return status;
  if (o.fx > 0) {
    scene->camera.image_width = first.cols;
    scene->camera.image_height = first.rows;
    scene->camera.fx = o.fx;
    scene->camera.fy = o.fy > 0 ? o.fy : o.fx;
    scene->camera.cx = o.cx >= 0 ? o.cx : 0.5 * (first.cols - 1);
    scene->camera.cy = o.cy >= 0 ? o.cy : 0.5 * (first.rows - 1);
    scene->camera_source = "--fx/--fy/--cx/--cy";
  } else {
    scene->camera = Camera::FromHorizontalFov(first.cols, first.rows, o.hfov_deg * M_PI / 180.0, 0);
    scene->camera_source = "--hfov";
  }
  return Status::Ok();
}

// Applies the overrides and checks the camera; `found` is the YAML that applies ("" if none).
Status FinishCamera(const CameraOverrides& overrides, const std::string& found,
                    const std::string& scene_path, InputScene* scene) {
  const bool pinhole_flags = overrides.camera_file.empty() && overrides.fx > 0;
  const bool fov_flag = overrides.camera_file.empty() && found.empty() && overrides.hfov_deg > 0;
  if (pinhole_flags || fov_flag) {
    if (!(overrides.hfov_deg >= 0 && overrides.hfov_deg < 180)) {
      return Status::InvalidArgument("--hfov must be in (0, 180) degrees");
    }
    Status status = CameraFromFlags(overrides, scene);
    if (!status.ok()) return status;
    if (overrides.camera_height != 0) scene->camera.mount_height = overrides.camera_height;
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

}  // namespace

Status ResolveInput(const std::string& input, const CameraOverrides& overrides,
                    std::vector<InputScene>* scenes) {
  scenes->clear();
  if (input.empty()) return Status::InvalidArgument("--input is required");
  const fs::path path(input);
  if (!Exists(path)) return Status::NotFound(input + ": no such file or folder");
  std::error_code ec;
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

Status CheckFirstFrameSize(const InputScene& scene) {
  if (scene.frames.empty()) return Status::Ok();
  const std::string& path = scene.frames.front().rgb_path;
  cv::Mat image;
  if (!ReadColorImage(path, &image).ok()) return Status::Ok();
  const Camera& camera = scene.camera;
  if (image.cols == camera.image_width && image.rows == camera.image_height) return Status::Ok();
  return Status::InvalidArgument(
      "image " + path + " is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
      " but the calibration " + scene.camera_source + " is for " +
      std::to_string(camera.image_width) + "x" + std::to_string(camera.image_height) +
      "; pass the camera of these images with --camera=FILE");
}

}  // namespace corridor
