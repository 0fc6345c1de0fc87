// The real photos' guard: the labelled photographs of tests/data/real-corridors/ recovered with the
// default options, as corridor_score runs them (the label's camera where it is known, a 60-degree
// horizontal field of view otherwise), and scored against the hand-labelled junctions
// (ScoreAgainstLabel: right when every labelled side is within 2% of the image height, ok but wrong
// beyond 5%). Of the photos that look along a corridor, none may be ok but wrong and at least
// kMinRight must be right: the bar the project is held to on real photos.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/image_io.h"
#include "corridor_depth/recover_depth.h"
#include "evaluation/junction_labels.h"

namespace corridor {
namespace {

const std::string kDir = std::string(CORRIDOR_SOURCE_DIR) + "/tests/data/real-corridors/";
constexpr int kMinRight = 9;

TEST(RealPhotosGuardTest, CorridorPhotosRightOrRefused) {
  std::vector<JunctionLabel> labels;
  ASSERT_TRUE(ReadJunctionLabels(kDir + "junctions.csv", &labels).ok());
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  int corridors = 0, right = 0;
  for (const JunctionLabel& label : labels) {
    if (label.kind != "corridor") continue;
    ++corridors;
    cv::Mat bgr;
    ASSERT_TRUE(ReadColorImage(kDir + label.file, &bgr).ok()) << label.file;
    Camera camera = Camera::FromHorizontalFov(label.width, label.height, M_PI / 3, 1.0);
    if (label.has_camera) {
      camera.fx = label.fx, camera.fy = label.fy, camera.cx = label.cx, camera.cy = label.cy;
    }
    RecoverDepthResult result;
    recoverer->Recover(bgr, camera, &result);
    const bool ok = result.status.ok() && result.has_geometry;
    const LabelScore score = ScoreAgainstLabel(label, ok, result.geometry, camera, result.roll);
    EXPECT_NE(score.verdict, LabelVerdict::kOkButWrong)
        << label.file << ": left " << score.side_error[0] << ", right " << score.side_error[1]
        << " of the height off; " << result.fallback;
    if (score.verdict == LabelVerdict::kRight) ++right;
    std::printf("%s: %s (left %.3f, right %.3f)\n", label.file.c_str(),
                LabelVerdictName(score.verdict), score.side_error[0], score.side_error[1]);
  }
  EXPECT_GE(corridors, 10);
  EXPECT_GE(right, kMinRight) << "of " << corridors << " corridor photos";
}

}  // namespace
}  // namespace corridor
