// Bad options: unknown solver or rasteriser names, empty or inverted grid ranges, a zero step,
// nonsense numbers; a negative thread count for corridor_eval. Rejected by
// DepthRecoverer::Create / RecoverDepth before any work with InvalidArgument naming the option
// (and the valid names), and by the tools with exit 2 before any output is written.

#include <gtest/gtest.h>

#include <functional>

#include "corridor_depth/recover_depth.h"
#include "tests/reliability/reliability_util.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::ExpectCleanExit;
using testing_util::ReliabilityCamera;
using testing_util::ReliabilityGeometry;
using testing_util::RunDepthTool;
using testing_util::ScratchDir;

struct BadOption {
  const char* name;
  std::function<void(RecoverDepthOptions*)> change;
  const char* message;
};

std::vector<BadOption> BadOptions() {
  return {
      {"unknown_solver", [](RecoverDepthOptions* o) { o->solver = "newton"; },
       "unknown solver 'newton'"},
      {"empty_solver", [](RecoverDepthOptions* o) { o->solver = ""; }, "empty solver name"},
      {"dangling_chain", [](RecoverDepthOptions* o) { o->solver = "closed_form+"; },
       "empty solver name"},
      {"unknown_rasterizer", [](RecoverDepthOptions* o) { o->rasterizer = "splat"; }, "splat"},
      {"grid_range_inverted",
       [](RecoverDepthOptions* o) {
         o->solver_options.grid.yaw_min = 0.3;
         o->solver_options.grid.yaw_max = -0.3;
       },
       "yaw range [0.3, -0.3] is empty or inverted"},
      {"grid_range_empty",
       [](RecoverDepthOptions* o) {
         o->solver_options.grid.width_min = 2;
         o->solver_options.grid.width_max = 2;
       },
       "width range [2, 2] is empty or inverted"},
      {"grid_step_zero", [](RecoverDepthOptions* o) { o->solver_options.grid.pitch_step = 0; },
       "pitch step 0 must be positive"},
      {"grid_step_negative",
       [](RecoverDepthOptions* o) { o->solver_options.grid.offset_step = -0.1; },
       "offset step -0.1 must be positive"},
      {"points_per_line_zero", [](RecoverDepthOptions* o) { o->points_per_line = 0; },
       "points_per_line"},
      {"solver_evidence_unknown", [](RecoverDepthOptions* o) { o->solver_evidence = "pixels"; },
       "solver_evidence must be lines or edges, not 'pixels'"},
      {"width_bounds_inverted",
       [](RecoverDepthOptions* o) {
         o->min_width = 5;
         o->max_width = 1;
       },
       "width bounds"},
      {"max_range_negative", [](RecoverDepthOptions* o) { o->rasterizer_options.max_range = -1; },
       "max_range"},
      {"roi_outside", [](RecoverDepthOptions* o) { o->perception.roi_top_fraction = 1.5; },
       "roi_top_fraction"},
      {"unknown_loss", [](RecoverDepthOptions* o) { o->solver_options.loss = "l3"; },
       "unknown loss 'l3'"},
  };
}

TEST(BadOptions, LibraryRejectsBeforeAnyWork) {
  const cv::Mat image =
      testing_util::RenderTestCorridor(ReliabilityCamera(), ReliabilityGeometry());
  for (const BadOption& bad : BadOptions()) {
    RecoverDepthOptions options;
    bad.change(&options);
    std::unique_ptr<DepthRecoverer> recoverer;
    Status status = DepthRecoverer::Create(options, &recoverer);
    EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << bad.name;
    EXPECT_TRUE(Contains(status.message(), bad.message)) << bad.name << ": " << status.ToString();
    EXPECT_EQ(recoverer, nullptr) << bad.name;
    RecoverDepthResult result;
    status = RecoverDepth(image, ReliabilityCamera(), options, &result);
    EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << bad.name;
    EXPECT_TRUE(result.depth.empty()) << bad.name;
    EXPECT_EQ(result.times.perception, 0.0) << bad.name << ": work was done";
  }
}

TEST(BadOptions, UnknownNamesListTheValidOnes) {
  RecoverDepthOptions options;
  options.solver = "newton";
  std::unique_ptr<DepthRecoverer> recoverer;
  Status status = DepthRecoverer::Create(options, &recoverer);
  EXPECT_TRUE(Contains(status.message(), "grid, closed_form, lm, joint")) << status.ToString();
  options = RecoverDepthOptions();
  options.rasterizer = "splat";
  status = DepthRecoverer::Create(options, &recoverer);
  EXPECT_TRUE(Contains(status.message(), "exact")) << status.ToString();
  EXPECT_TRUE(Contains(status.message(), "paper")) << status.ToString();
}

// A folder with one good corridor and its camera, to show that nothing is written.
std::string GoodInput(const ScratchDir& dir) {
  dir.WriteCamera("in/camera.yaml", ReliabilityCamera());
  dir.WriteImage("in/000.png",
                 testing_util::RenderTestCorridor(ReliabilityCamera(), ReliabilityGeometry()));
  return dir.Path("in");
}

TEST(BadOptions, DepthToolExitsTwoBeforeAnyWork) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--solver=newton", "unknown solver 'newton'"},
      {"--solver=", "empty solver name"},
      {"--rasterizer=splat", "splat"},
      {"--points_per_line=0", "points_per_line"},
      {"--solver_evidence=pixels", "solver_evidence"},
      {"--max_range=-1", "max_range"},
      {"--roi_top=2", "roi_top_fraction"},
      {"--ceiling_height=-2", "ceiling_height"},
      {"--max_width_change=1.5", "max_width_change"},
      {"--max_ceiling_disagreement=-1", "max_ceiling_disagreement"},
      {"--max_ceiling_change=1", "max_ceiling_change"},
      {"--vis_max_depth=0", "--vis_max_depth"},
      {"--no_such_flag=1", "no_such_flag"},
      {"stray_argument", "unexpected argument 'stray_argument'"},
  };
  for (const auto& [flag, message] : cases) {
    SCOPED_TRACE(flag);
    ScratchDir dir;
    const auto run = RunDepthTool(GoodInput(dir), dir.Path("out"), dir, {flag});
    ExpectCleanExit(run, 2, {message});
    EXPECT_FALSE(testing_util::Exists(dir.Path("out")));
  }
}

TEST(BadOptions, DepthToolNeedsInputAndOutput) {
  ScratchDir dir;
  auto run =
      testing_util::RunTool(testing_util::kDepthTool, {"--output_dir=" + dir.Path("o")}, dir);
  ExpectCleanExit(run, 2, {"--input is required"});
  run = testing_util::RunTool(testing_util::kDepthTool, {"--input=" + GoodInput(dir)}, dir);
  ExpectCleanExit(run, 2, {"--output_dir is required"});
}

TEST(BadOptions, EvalToolRejectsNegativeThreadsBeforeAnyWork) {
  ScratchDir dir;
  dir.WriteCamera("data/scene/camera.yaml", ReliabilityCamera());
  dir.WriteImage("data/scene/rgb/000.png",
                 testing_util::RenderTestCorridor(ReliabilityCamera(), ReliabilityGeometry()));
  for (const char* flag : {"--threads=-1", "--solver=newton", "--no_such_flag=1"}) {
    SCOPED_TRACE(flag);
    const auto run = testing_util::RunTool(
        testing_util::kEvalTool,
        {"--dataset=" + dir.Path("data"), "--output_dir=" + dir.Path("out"), flag}, dir);
    ExpectCleanExit(run, 2, {std::string(flag).substr(2, std::string(flag).find('=') - 2)});
    EXPECT_FALSE(testing_util::Exists(dir.Path("out")));
  }
}

}  // namespace
}  // namespace corridor
