#pragma once

// The README's demo corridor, as `corridor_synth --preset=sequence --frames=12 --seed=7`
// (scripts/run_demo.sh) renders it: corridor_synth's flag defaults for the sequence preset
// (tools/corridor_synth_main.cc), spelled out. A change of those defaults changes the demo, and
// must change this too.

#include <cmath>

#include "corridor_depth/camera.h"
#include "synth/presets.h"
#include "synth/sequence.h"

namespace corridor {
namespace testing_util {

inline synth::ScenePreset DemoCorridor(int frames = 12, uint32_t seed = 7) {
  synth::ScenePreset preset;
  preset.name = "corridor";
  synth::SceneOptions& s = preset.scene;
  s.width = 2.2;
  s.ceiling_height = 2.7;
  s.length = 40;
  s.clutter = 0.2;
  s.door_density = 0.5;
  s.floor_wall_contrast = 0.9;
  s.seed = seed;
  preset.camera = Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180.0, 0.66);
  synth::SequenceOptions sequence;
  sequence.frames = frames;
  sequence.base = {0.05, 0.0, 0.0, 0.66, 2.0};  // pitch, yaw, offset, height, distance.
  sequence.seed = seed;
  preset.poses = synth::MakeSequence(sequence);
  return preset;
}

}  // namespace testing_util
}  // namespace corridor
