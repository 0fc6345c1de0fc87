// The layout and the chosen solver (pipeline/chosen_solve.h): on a generated corridor, every
// solver and evidence sees the same junctions and ceiling (the layout is decided once), and the
// geometry reported is the named solver's own estimate from them, checked by solving those
// junctions again here; a solver whose estimate is implausible is refused and changes nothing. On
// frames where the solvers' estimates differ enough to sway the frame's checks, the frame is
// still judged on the layout: its confidence, evidence and end wall are the default run's.
#include <cmath>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "pipeline/chosen_solve.h"
#include "pipeline/solver_evidence.h"
#include "tests/support/corridor_frame.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

Camera TestCamera() { return Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180, 0.7); }

// The test corridor, rendered, and its recovery with the default options into *result.
synth::Frame DefaultRecovery(const Camera& camera, RecoverDepthResult* result) {
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, 2.2, 2.8, 5, synth::CameraPose{0.06, 0.04, 0.25, 0.7, 3.0});
  EXPECT_FALSE(frame.bgr.empty());
  EXPECT_TRUE(RecoverDepth(frame.bgr, camera, RecoverDepthOptions(), result).ok())
      << result->status.ToString();
  return frame;
}

void ExpectSameEvidence(const FrameEvidence& a, const FrameEvidence& b) {
  EXPECT_DOUBLE_EQ(a.ceiling_disagreement, b.ceiling_disagreement);
  EXPECT_DOUBLE_EQ(a.ceiling_split, b.ceiling_split);
  EXPECT_EQ(a.corrected, b.corrected);
  EXPECT_EQ(a.moved_side, b.moved_side);
  for (int s = 0; s < 2; ++s) {
    EXPECT_DOUBLE_EQ(a.junction[s], b.junction[s]);
    EXPECT_DOUBLE_EQ(a.floor_across[s], b.floor_across[s]);
    EXPECT_EQ(a.crossings[s].crossing, b.crossings[s].crossing);
    EXPECT_EQ(a.crossings[s].reaching, b.crossings[s].reaching);
  }
}

TEST(ChosenSolveTest, EverySolverSeesOneLayoutAndReportsItsOwnEstimate) {
  const Camera camera = TestCamera();
  RecoverDepthResult layout;
  const synth::Frame frame = DefaultRecovery(camera, &layout);
  ASSERT_TRUE(layout.status.ok());
  for (const std::string evidence : {"lines", "edges"}) {
    CorridorGeometry joint;
    for (const std::string solver : {"joint", "grid", "closed_form+lm"}) {
      SCOPED_TRACE(solver + " on " + evidence);
      RecoverDepthOptions options;
      options.solver = solver;
      options.solver_evidence = evidence;
      RecoverDepthResult result;
      ASSERT_TRUE(RecoverDepth(frame.bgr, camera, options, &result).ok())
          << result.status.ToString();
      // One layout: the junction lines are those of the default run, whatever the solver.
      for (int k = 0; k < 3; ++k) {
        EXPECT_DOUBLE_EQ(result.junctions.left.line[k], layout.junctions.left.line[k]);
        EXPECT_DOUBLE_EQ(result.junctions.right.line[k], layout.junctions.right.line[k]);
      }
      // The ceiling is searched for the layout's walls: its height is the default run's.
      EXPECT_DOUBLE_EQ(result.geometry.ceiling_height, layout.geometry.ceiling_height);
      // The solver's own estimate from those junctions, solved again here.
      std::unique_ptr<CorridorSolver> direct;
      ASSERT_TRUE(CreateSolver(solver, options.solver_options, &direct).ok());
      const CorridorObservation observation =
          ObservationFromJunctions(result.junctions, camera, options);
      SolverSummary summary;
      ASSERT_TRUE(direct->Solve(observation, nullptr, &summary).ok());
      EXPECT_NEAR(result.geometry.width, summary.estimate.width, 1e-9);
      EXPECT_NEAR(result.geometry.yaw, summary.estimate.yaw, 1e-12);
      EXPECT_NEAR(result.geometry.pitch, summary.estimate.pitch, 1e-12);
      EXPECT_NEAR(result.geometry.offset, summary.estimate.offset, 1e-9);
      EXPECT_NEAR(result.geometry.width, frame.truth.width, 0.02 * frame.truth.width);
      if (solver == "joint") {
        joint = result.geometry;
      } else if (solver == "grid") {
        // The grid's steps put it off the exact fit: its own answer, not the layout's.
        EXPECT_GT(std::abs(result.geometry.yaw - joint.yaw) +
                      std::abs(result.geometry.pitch - joint.pitch) +
                      std::abs(result.geometry.width - joint.width),
                  1e-7);
      }
    }
  }
}

// Frames of the generator's mixed class whose confidence, measured on each solver's own
// estimate, differed between solvers on the edge points (0.7 for `joint`, 1 for `closed_form`,
// with the layout's joint-on-lines 0.7, on the first).
TEST(ChosenSolveTest, TheFrameIsJudgedOnTheLayoutWhateverTheSolver) {
  for (const auto& [scene, index] : {std::pair{2, 7}, std::pair{6, 6}}) {
    SCOPED_TRACE("mix scene " + std::to_string(scene) + " frame " + std::to_string(index));
    const testing_util::PresetFrame f = testing_util::RenderPreset("mix", scene, index);
    ASSERT_FALSE(f.frame.bgr.empty());
    RecoverDepthResult layout;
    ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &layout).ok());
    for (const std::string solver : {"joint", "closed_form", "lm"}) {
      SCOPED_TRACE(solver);
      RecoverDepthOptions options;
      options.solver = solver;
      options.solver_evidence = "edges";
      RecoverDepthResult result;
      ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &result).ok())
          << result.status.ToString();
      EXPECT_DOUBLE_EQ(result.confidence, layout.confidence);
      ExpectSameEvidence(result.evidence, layout.evidence);
      EXPECT_DOUBLE_EQ(result.geometry.end_distance, layout.geometry.end_distance);
      EXPECT_DOUBLE_EQ(result.roll, layout.roll);
      for (int k = 0; k < 3; ++k) {
        EXPECT_DOUBLE_EQ(result.junctions.left.line[k], layout.junctions.left.line[k]);
        EXPECT_DOUBLE_EQ(result.junctions.right.line[k], layout.junctions.right.line[k]);
      }
    }
  }
}

// A solver that always answers `estimate`.
class FixedSolver : public CorridorSolver {
 public:
  explicit FixedSolver(const CorridorGeometry& estimate) : estimate_(estimate) {}
  std::string Name() const override { return "fixed"; }
  Status Solve(const CorridorObservation&, const CorridorGeometry*,
               SolverSummary* summary) const override {
    summary->estimate = estimate_;
    return Status::Ok();
  }

 private:
  CorridorGeometry estimate_;
};

TEST(ChosenSolveTest, AnImplausibleEstimateIsRefusedAndChangesNothing) {
  const Camera camera = TestCamera();
  RecoverDepthResult result;
  DefaultRecovery(camera, &result);
  ASSERT_TRUE(result.status.ok());
  const RecoverDepthOptions options;
  const CorridorGeometry before = result.geometry;
  CorridorGeometry implausible = before;
  implausible.offset = before.width;  // The camera outside the walls.
  CorridorGeometry geometry = before;
  SolverSummary summary;
  summary.solver_name = "untouched";
  const Status status = ChosenSolve(FixedSolver(implausible), options, result.junctions, camera,
                                    &geometry, &summary);
  EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry) << status.ToString();
  EXPECT_EQ(geometry.width, before.width);
  EXPECT_EQ(geometry.offset, before.offset);
  EXPECT_EQ(summary.solver_name, "untouched");

  // A plausible estimate is taken, with the frame's camera and ceiling heights.
  CorridorGeometry plausible = before;
  plausible.width = 1.01 * before.width;
  plausible.camera_height = 0;
  plausible.ceiling_height = 0;
  ASSERT_TRUE(ChosenSolve(FixedSolver(plausible), options, result.junctions, camera, &geometry,
                          &summary)
                  .ok());
  EXPECT_EQ(geometry.width, plausible.width);
  EXPECT_EQ(geometry.camera_height, before.camera_height);
  EXPECT_EQ(geometry.ceiling_height, before.ceiling_height);
}

TEST(ChosenSolveTest, TheLayoutIsJointOnLines) {
  RecoverDepthOptions options;
  options.solver = "grid";
  options.solver_evidence = "edges";
  const RecoverDepthOptions layout = LayoutOptions(options);
  EXPECT_EQ(layout.solver, "joint");
  EXPECT_EQ(layout.solver_evidence, "lines");
  EXPECT_TRUE(ChosenSolveDiffers(options));
  EXPECT_TRUE(ChosenSolveDiffers(RecoverDepthOptions()));  // joint on edges by default.
  RecoverDepthOptions on_lines;
  on_lines.solver_evidence = "lines";
  EXPECT_FALSE(ChosenSolveDiffers(on_lines));  // The layout's own solve: it runs once.
}

}  // namespace
}  // namespace corridor
