#pragma once

#include <cstdint>

#include <gtest/gtest.h>

#include "core/camera.h"
#include "synth/corridor_renderer.h"

namespace corridor {
namespace testing_util {

// One frame of a generated corridor (the generator's ray caster, with its truth), for the tests
// that need a plain scene: the scene options they vary, the rest the generator's defaults.
// Empty (and a test failure) when it cannot be rendered.
inline synth::Frame RenderCorridorFrame(const Camera& camera, double width, double ceiling_height,
                                        uint32_t seed, const synth::CameraPose& pose,
                                        double clutter = synth::SceneOptions().clutter) {
  synth::SceneOptions scene;
  scene.width = width;
  scene.ceiling_height = ceiling_height;
  scene.clutter = clutter;
  scene.seed = seed;
  synth::Frame frame;
  EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(scene), camera, pose, &frame).ok());
  return frame;
}

}  // namespace testing_util
}  // namespace corridor
