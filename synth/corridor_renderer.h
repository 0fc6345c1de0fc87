#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "synth/corridor_scene.h"
#include "synth/scene_options.h"

namespace corridor {
namespace synth {

// One rendered frame and its ground truth.
struct Frame {
  cv::Mat bgr;             // CV_8UC3 image.
  cv::Mat depth;           // CV_32F camera-frame z of the first surface hit, m (0 = none).
  CorridorGeometry truth;  // yaw, pitch, offset, width, camera_height, ceiling_height.
};

// Ray-casts the corridor for a pinhole camera (distortion ignored) at the pose: floor tiles with
// grout (or carpet, runners, stripes), painted walls with baseboards (and wainscots), recessed
// doors with frames, glass runs (the plane is the surface, the colour the room behind), window
// bands, ceiling and light panels, solid boxes (clutter, rails, furniture, pillars, sills), and
// the end wall; a rolled camera when pose.roll != 0; Lambert shading with a light at the camera, falloff with distance,
// 2x2 supersampling, then blur and sensor noise. Deterministic for given inputs.
Status RenderFrame(const SceneOptions& options, const Camera& camera, const CameraPose& pose,
                   Frame* frame);

// The same for a scene built once (BuildScene) and reused across the frames of a sequence.
Status RenderFrame(const CorridorScene& scene, const Camera& camera, const CameraPose& pose,
                   Frame* frame);

}  // namespace synth
}  // namespace corridor
