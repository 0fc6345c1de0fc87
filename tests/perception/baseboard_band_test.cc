// The baseboard rule's band test on generated corridors, against the generator's junction lines.
// Cord_H03 of the paper preset has a grey baseboard on a pinkish-brown floor: the baseboard's top
// (grey on beige) is the stronger edge, and the pair choice takes it; the band between it and the
// lower line is unlike the floor, so the lower line is taken. Cord_E06 has a floor line just below
// its left junction: the band between them is floor, and the junction stays.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "perception/junction_detector.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

// Largest distance, px, of the found left junction's support ends from the true line.
double LeftOffsetPx(const synth::ScenePreset& preset, const synth::Frame& frame,
                    const JunctionDetectorOptions& options) {
  JunctionPair pair;
  EXPECT_TRUE(DetectJunctions(frame.bgr, options, &pair).ok());
  EXPECT_TRUE(pair.status.ok()) << pair.status.ToString();
  const Eigen::Vector3d truth = testing_util::TrueJunction(frame.truth, preset.camera, -1);
  return std::max(std::abs(truth.dot(pair.left.near_end.homogeneous())),
                  std::abs(truth.dot(pair.left.far_end.homogeneous())));
}

struct Offsets {
  double with_band, without_band;
};

Offsets LeftOffsets(const std::string& scene, size_t pose) {
  const synth::ScenePreset preset = testing_util::PaperScene(scene);
  synth::Frame frame;
  EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera,
                                 preset.poses.at(pose), &frame)
                  .ok());
  JunctionDetectorOptions without;
  without.baseboard_band_contrast = 0;
  const Offsets offsets{LeftOffsetPx(preset, frame, JunctionDetectorOptions()),
                        LeftOffsetPx(preset, frame, without)};
  std::printf(
      "%s frame %zu: left junction %.1f px from the truth with the band test, %.1f px "
      "without\n",
      scene.c_str(), pose, offsets.with_band, offsets.without_band);
  return offsets;
}

TEST(BaseboardBandTest, ALowContrastBaseboardsLowerEdgeIsTaken) {
  for (size_t pose : {0, 2, 3, 4, 5, 6}) {
    const Offsets offsets = LeftOffsets("Cord_H03", pose);
    EXPECT_GT(offsets.without_band, 4.0) << "frame " << pose;  // The premise: the top is taken.
    EXPECT_LT(offsets.with_band, 2.0) << "frame " << pose;
  }
}

TEST(BaseboardBandTest, AFloorLineBelowTheJunctionIsNotTaken) {
  for (size_t pose : {5, 6, 12, 14}) {
    const synth::ScenePreset preset = testing_util::PaperScene("Cord_E06");
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(synth::BuildScene(preset.scene), preset.camera,
                                   preset.poses.at(pose), &frame)
                    .ok());
    // The premise: a band test that takes any lower line takes a line off the junction.
    JunctionDetectorOptions eager;
    eager.baseboard_band_contrast = 1e-6;
    const double eager_offset = LeftOffsetPx(preset, frame, eager);
    const double offset = LeftOffsetPx(preset, frame, JunctionDetectorOptions());
    std::printf(
        "Cord_E06 frame %zu: left junction %.1f px from the truth, %.1f px when any lower "
        "line is taken\n",
        pose, offset, eager_offset);
    EXPECT_GT(eager_offset, 4.0) << "frame " << pose;
    EXPECT_LT(offset, 2.0) << "frame " << pose;
  }
}

}  // namespace
}  // namespace corridor
