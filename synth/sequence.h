#pragma once

#include <cstdint>
#include <vector>

#include "synth/scene_options.h"

namespace corridor {
namespace synth {

// A robot driving along the corridor: the pose drifts smoothly around `base`.
struct SequenceOptions {
  int frames = 15;                 // Number of poses, >= 1.
  double step = 0.35;              // Distance driven between frames, m.
  CameraPose base;                 // Mean pose; base.distance is where the first frame is.
  double yaw_amplitude = 0.04;     // Yaw wander, rad.
  double pitch_amplitude = 0.01;   // Pitch wander (suspension), rad.
  double offset_amplitude = 0.08;  // Lateral wander, m.
  uint32_t seed = 1;               // Phases of the wander.
};

std::vector<CameraPose> MakeSequence(const SequenceOptions& options);

}  // namespace synth
}  // namespace corridor
