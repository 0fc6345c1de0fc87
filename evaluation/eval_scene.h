#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "io/dataset.h"

namespace corridor {

// One scene of image files to evaluate: the frames of a dataset scene (io/dataset.h) or of a
// folder, with the camera they were taken with.
struct EvalScene {
  std::string name;                  // Scene name: the output folder and the report's row.
  Camera camera;                     // Checked, with a positive mount height.
  std::vector<DatasetFrame> frames;  // In order; depth/truth paths where the dataset has them.
  // > 0: each image gets a pinhole of its own size with this horizontal field of view (degrees)
  // and is read upright (EXIF orientation), as a photo viewer shows it; `camera` then serves only
  // for its mount height and for frames that cannot be read. 0: `camera` serves every frame and
  // images are read as stored (a calibration is for the image as stored).
  double per_image_hfov_deg = 0;
};

// The camera of one image: `scene_camera`, or, when per_image_hfov_deg > 0, a pinhole of the
// image's own size with that field of view and scene_camera's mount height.
Camera PerImageCamera(const Camera& scene_camera, double per_image_hfov_deg,
                      const cv::Size& image_size);

// PerImageCamera for a frame of `scene`.
Camera FrameCamera(const EvalScene& scene, const cv::Size& image_size);

// A dataset scene (LoadDataset) as an EvalScene: its name, camera and frames.
EvalScene EvalSceneFromDataset(const DatasetScene& scene);

}  // namespace corridor
