#include "corridor_depth/evaluation.h"

#include <cmath>

namespace corridor {

Camera PerImageCamera(const Camera& scene_camera, double per_image_hfov_deg,
                      const cv::Size& image_size) {
  if (!(per_image_hfov_deg > 0)) return scene_camera;
  return Camera::FromHorizontalFov(image_size.width, image_size.height,
                                   per_image_hfov_deg * M_PI / 180.0, scene_camera.mount_height);
}

Camera FrameCamera(const EvalScene& scene, const cv::Size& image_size) {
  return PerImageCamera(scene.camera, scene.per_image_hfov_deg, image_size);
}

EvalScene EvalSceneFromDataset(const DatasetScene& scene) {
  EvalScene out;
  out.name = scene.name;
  out.camera = scene.camera;
  out.frames = scene.frames;
  return out;
}

}  // namespace corridor
