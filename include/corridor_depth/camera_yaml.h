#pragma once

#include <string>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"

namespace corridor {

// Reads a ROS camera_info YAML (image_width, image_height, camera_matrix, distortion_model,
// distortion_coefficients) plus the extra key camera_height (metres; 0 when absent).
// Every error names the file and the key that is wrong. Checks intrinsics, not the height.
Status ReadCameraYaml(const std::string& path, Camera* camera);
// The same from YAML text in memory; `name` stands for the file in messages.
Status ParseCameraYaml(const std::string& text, const std::string& name, Camera* camera);

// Writes the same format (plumb_bob); atomic (temporary name, then rename).
Status WriteCameraYaml(const std::string& path, const Camera& camera);

}  // namespace corridor
