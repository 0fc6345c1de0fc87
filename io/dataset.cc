#include "corridor_depth/dataset.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <system_error>

#include "corridor_depth/camera_yaml.h"
#include "io/file_util.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;

bool IsDir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool IsFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

std::string SizeString(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

// The scene folders of a dataset root, sorted by name: root itself when it has rgb/, otherwise
// every subfolder with rgb/.
Status FindSceneDirs(const fs::path& root, std::vector<fs::path>* dirs) {
  dirs->clear();
  if (IsDir(root / "rgb")) {
    dirs->push_back(root);
    return Status::Ok();
  }
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    if (IsDir(it->path()) && IsDir(it->path() / "rgb")) dirs->push_back(it->path());
  }
  if (ec) return Status::IoError(root.string() + ": cannot list folder: " + ec.message());
  std::sort(dirs->begin(), dirs->end(),
            [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
  return Status::Ok();
}

// The folder's own name, also for "data/" and ".".
std::string FolderName(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(dir, ec);
  if (ec) p = dir.lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  return p.filename().string();
}

// Picks <scene>/camera.yaml, else <root>/camera.yaml, and reads it.
Status LoadSceneCamera(const fs::path& root, DatasetScene* scene) {
  const fs::path own = fs::path(scene->dir) / "camera.yaml";
  const fs::path shared = root / "camera.yaml";
  if (IsFile(own)) {
    scene->camera_path = own.string();
  } else if (IsFile(shared)) {
    scene->camera_path = shared.string();
  } else {
    std::string message = "scene " + scene->name + " has no camera calibration: neither " +
                          own.string();
    if (own != shared) message += " nor " + shared.string();
    return Status::NotFound(message + " exists");
  }
  return ReadCameraYaml(scene->camera_path, &scene->camera);
}

Status LoadFrames(DatasetScene* scene) {
  const fs::path dir(scene->dir);
  std::vector<std::string> images;
  Status status = ListImages((dir / "rgb").string(), &images);
  if (!status.ok()) return status;

  std::map<std::string, FrameTruth> truth_by_file;
  const fs::path truth_path = dir / "truth.yaml";
  if (IsFile(truth_path)) {
    std::vector<FrameTruth> truths;
    status = ReadTruthYaml(truth_path.string(), &truths);
    if (!status.ok()) return status;
    for (FrameTruth& t : truths) truth_by_file[t.file] = std::move(t);
  }

  std::map<std::string, std::string> first_path_of_name;
  for (const std::string& rgb : images) {
    DatasetFrame frame;
    const fs::path p(rgb);
    frame.name = p.stem().string();
    frame.rgb_path = rgb;
    const auto [it, inserted] = first_path_of_name.emplace(frame.name, rgb);
    if (!inserted) {
      return Status::InvalidArgument(rgb + ": frame name '" + frame.name + "' is also used by " +
                                     it->second + "; depth and masks would be ambiguous");
    }
    const fs::path depth = dir / "depth" / (frame.name + ".png");
    if (IsFile(depth)) frame.depth_path = depth.string();
    const fs::path floor = dir / "floor" / (frame.name + ".png");
    if (IsFile(floor)) frame.floor_mask_path = floor.string();
    const auto truth = truth_by_file.find(p.filename().string());
    if (truth != truth_by_file.end()) {
      frame.has_truth = true;
      frame.truth = truth->second;
    }
    scene->frames.push_back(std::move(frame));
  }
  std::sort(scene->frames.begin(), scene->frames.end(),
            [](const DatasetFrame& a, const DatasetFrame& b) { return a.name < b.name; });
  return Status::Ok();
}

}  // namespace

bool IsDatasetRoot(const std::string& dir) {
  std::vector<fs::path> dirs;
  return IsDir(dir) && FindSceneDirs(dir, &dirs).ok() && !dirs.empty();
}

Status LoadDataset(const std::string& root, std::vector<DatasetScene>* scenes) {
  scenes->clear();
  const fs::path root_path(root);
  std::error_code ec;
  if (!fs::exists(root_path, ec)) return Status::NotFound(root + ": dataset folder does not exist");
  if (!IsDir(root_path)) return Status::InvalidArgument(root + ": dataset path is not a folder");
  std::vector<fs::path> dirs;
  Status status = FindSceneDirs(root_path, &dirs);
  if (!status.ok()) return status;
  if (dirs.empty()) {
    return Status::NotFound(root + ": no scenes (no rgb/ folder in it or in any subfolder)");
  }
  std::vector<DatasetScene> result;
  for (const fs::path& dir : dirs) {
    DatasetScene scene;
    scene.dir = dir.string();
    scene.name = FolderName(dir);
    status = LoadSceneCamera(root_path, &scene);
    if (status.ok()) status = LoadFrames(&scene);
    if (!status.ok()) return status;
    result.push_back(std::move(scene));
  }
  *scenes = std::move(result);
  return Status::Ok();
}

Status CheckDepthMatchesImage(const std::string& depth_path, const cv::Size& image_size,
                              const cv::Mat& depth) {
  if (depth.size() == image_size) return Status::Ok();
  return Status::InvalidArgument("depth image " + depth_path + " is " + SizeString(depth.size()) +
                                 " but its colour image is " + SizeString(image_size));
}

Status ListImages(const std::string& dir, std::vector<std::string>* paths) {
  static const std::set<std::string> kExtensions = {".png", ".jpg", ".jpeg", ".bmp",
                                                    ".tif", ".tiff"};
  paths->clear();
  std::error_code ec;
  if (!fs::exists(dir, ec)) return Status::NotFound(dir + ": image folder does not exist");
  if (!IsDir(dir)) return Status::InvalidArgument(dir + ": is not a folder");
  std::vector<std::string> found;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    // Hidden files include the temporaries of the atomic writers and macOS "._x.png" debris.
    if (name.empty() || name[0] == '.' || !IsFile(it->path())) continue;
    if (kExtensions.count(LowerExtension(name)) > 0) found.push_back(it->path().string());
  }
  if (ec) return Status::IoError(dir + ": cannot list folder: " + ec.message());
  if (found.empty()) {
    return Status::NotFound(dir + ": holds no images (png, jpg, jpeg, bmp, tif, tiff)");
  }
  std::sort(found.begin(), found.end());
  *paths = std::move(found);
  return Status::Ok();
}

Status MakeSceneDirs(const std::string& root, const std::string& scene, std::string* rgb_dir,
                     std::string* depth_dir) {
  const fs::path scene_name(scene);
  if (scene.empty() || scene_name.has_parent_path() || scene == "." || scene == "..") {
    return Status::InvalidArgument("scene name '" + scene + "' must be a plain folder name");
  }
  const fs::path base = fs::path(root) / scene_name;
  for (const fs::path& dir : {base / "rgb", base / "depth"}) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !IsDir(dir)) {
      return Status::IoError(dir.string() + ": cannot create folder" +
                             (ec ? ": " + ec.message() : std::string()));
    }
  }
  *rgb_dir = (base / "rgb").string();
  *depth_dir = (base / "depth").string();
  return Status::Ok();
}

}  // namespace corridor
