// A large image of a tiled corridor: the paper preset's Cord_E01 and Cord_E04 rendered at three
// times the pixels (1260x1080, corridor_synth --paper_scale=3), where the floor's grout lines and
// their shadows are resolved. The junction search halves the image; its appearance probes must
// reach as far into the scene as at the paper's size, or a grout line's shadow passes for the
// wall above a junction and both walls come out 9-12% too near. The width must follow
// the generator's truth.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

TEST(LargeImageTest, TiledFloorsGroutLinesAreNotTakenForJunctions) {
  int tested = 0;
  for (const auto& preset : synth::PaperPreset(3.0)) {
    if (preset.name != "Cord_E01" && preset.name != "Cord_E04") continue;
    ASSERT_EQ(preset.camera.image_width, 1260);
    const synth::CorridorScene scene = synth::BuildScene(preset.scene);
    for (const int index : {0, 7}) {
      synth::Frame frame;
      ASSERT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses.at(index), &frame).ok());
      RecoverDepthResult result;
      ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, RecoverDepthOptions(), &result).ok())
          << result.status.ToString();
      const double truth = frame.truth.width;
      EXPECT_LT(std::abs(result.geometry.width - truth) / truth, 0.03)
          << preset.name << " frame " << index << ": " << result.geometry.width << " m against "
          << truth << " m";
      ++tested;
    }
  }
  EXPECT_EQ(tested, 4);
}

}  // namespace
}  // namespace corridor
