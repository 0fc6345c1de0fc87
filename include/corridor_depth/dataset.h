#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"
#include "corridor_depth/truth_yaml.h"

namespace corridor {

// The dataset layout:
//   <dataset>/<scene>/rgb/<frame>.png, <dataset>/<scene>/depth/<frame>.png (16-bit mm),
//   <dataset>/<scene>/camera.yaml (or <dataset>/camera.yaml for every scene without one),
//   <dataset>/<scene>/truth.yaml (optional), <dataset>/<scene>/floor/<frame>.png (optional).
struct DatasetFrame {
  std::string name;             // The file name without extension, e.g. "000003".
  std::string rgb_path;         // Colour image.
  std::string depth_path;       // Ground-truth depth; empty when the scene has none for it.
  std::string floor_mask_path;  // Floor mask (255 = floor); empty when absent.
  bool has_truth = false;       // True when truth.yaml lists this frame.
  FrameTruth truth;             // Valid when has_truth.
};

struct DatasetScene {
  std::string name;                  // The scene folder's name.
  std::string dir;                   // Its path.
  std::string camera_path;           // The camera.yaml that applies: the scene's, else the root's.
  Camera camera;                     // Read from camera_path (mount_height 0 if key absent).
  std::vector<DatasetFrame> frames;  // Sorted by name.
};

// True when `dir` looks like a dataset root: it has at least one <scene>/rgb/ folder, or an rgb/
// folder of its own (a single-scene dataset, as LoadDataset accepts).
bool IsDatasetRoot(const std::string& dir);

// Loads every scene (sorted by name). A scene without any camera.yaml, a malformed YAML: each is
// an error that names the file. If `root` itself has an rgb/ folder it is loaded as the only
// scene. Images are not opened here: a depth image whose size differs from its colour image is
// checked lazily by callers via CheckDepthMatchesImage.
Status LoadDataset(const std::string& root, std::vector<DatasetScene>* scenes);

// InvalidArgument naming depth_path when `depth` (as read from depth_path) is not image_size:
// "depth image <path> is 640x480 but its colour image is 320x240".
Status CheckDepthMatchesImage(const std::string& depth_path, const cv::Size& image_size,
                              const cv::Mat& depth);

// Lists the image files (png, jpg, jpeg, bmp, tif, tiff; case-insensitive) in a folder, sorted.
Status ListImages(const std::string& dir, std::vector<std::string>* paths);

// Creates <root>/<scene>/{rgb,depth} (and returns their paths) for writers such as the generator.
Status MakeSceneDirs(const std::string& root, const std::string& scene, std::string* rgb_dir,
                     std::string* depth_dir);

}  // namespace corridor
