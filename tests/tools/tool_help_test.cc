// The four tools' --help, -h and --version, run as binaries: exit 0, each tool's own flags listed
// (names written out here, not read from the tools), none of glog's or gflags' own; and
// corridor_synth's renamed --hfov_deg, which must warn and give the same camera as --hfov.
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/reliability/reliability_util.h"

namespace corridor {
namespace {

using testing_util::RunTool;
using testing_util::ScratchDir;
using testing_util::ToolRun;

struct ToolCase {
  const char* name;
  std::vector<std::string> own_flags;
};

const std::vector<ToolCase>& Tools() {
  static const std::vector<ToolCase> tools = {
      {"corridor_depth",
       {"input", "output_dir", "camera", "hfov", "fx", "focal", "camera_height", "solver",
        "rasterizer", "max_range", "write_vis", "write_cloud", "skip_existing", "output_bag",
        "image_topic", "relaxed_hough_threshold", "sequence", "min_confidence", "write_model_fit"}},
      {"corridor_eval",
       {"dataset", "output_dir", "caps", "threads", "compare", "solver", "rasterizer", "hfov",
        "camera_height", "write_depth", "vis_max_error"}},
      {"corridor_synth",
       {"preset", "output_dir", "paper_scale", "scene_name", "width_px", "height_px", "fx", "hfov",
        "corridor_width", "ceiling_height", "length", "camera_height", "pitch", "yaw", "offset",
        "distance", "clutter", "door_density", "contrast", "frames", "seed"}},
      {"solver_compare",
       {"output_dir", "solvers", "noise", "outliers", "trials", "seed", "dataset", "loss",
        "loss_scale"}},
      {"corridor_score", {"labels", "output_dir", "tile_width", "hfov", "min_confidence", "solver"}},
  };
  return tools;
}

// Flags of glog and gflags that a tool's --help must not list.
const char* const kForeignFlags[] = {"logtostderr", "alsologtostderr", "v", "vmodule",
                                     "minloglevel", "stderrthreshold", "log_dir", "flagfile",
                                     "fromenv", "tryfromenv", "undefok", "helpfull",
                                     "helpxml", "log_prefix", "logbuflevel"};

std::string ToolPath(const std::string& name) {
  return std::string(CORRIDOR_BINARY_DIR) + "/tools/" + name;
}

// The flag names the help lists: lines that start (after indentation) with --NAME or --[no]NAME.
std::set<std::string> ListedFlags(const std::string& help) {
  std::set<std::string> names;
  const std::regex line(R"(^\s+--(?:\[no\])?([a-z0-9_]+))");
  size_t begin = 0;
  while (begin < help.size()) {
    size_t end = help.find('\n', begin);
    if (end == std::string::npos) end = help.size();
    std::smatch match;
    const std::string text = help.substr(begin, end - begin);
    if (std::regex_search(text, match, line)) names.insert(match[1]);
    begin = end + 1;
  }
  return names;
}

TEST(ToolHelpTest, HelpListsOwnFlagsOnlyAndExitsZero) {
  ScratchDir scratch;
  for (const auto& tool : Tools()) {
    for (const char* flag : {"--help", "-h"}) {
      const ToolRun run = RunTool(ToolPath(tool.name), {flag}, scratch);
      ASSERT_TRUE(run.started) << tool.name;
      EXPECT_EQ(run.exit_code, 0) << tool.name << " " << flag << "\n"
                                  << run.err;
      const std::set<std::string> listed = ListedFlags(run.out);
      for (const auto& own : tool.own_flags) {
        EXPECT_EQ(listed.count(own), 1u) << tool.name << " " << flag << " does not list --" << own;
      }
      for (const char* foreign : kForeignFlags) {
        EXPECT_EQ(listed.count(foreign), 0u) << tool.name << " " << flag << " lists --" << foreign;
      }
      for (const char* group : {"Input:", "Output:"}) {
        EXPECT_NE(run.out.find(std::string("\n") + group + "\n"), std::string::npos)
            << tool.name << " has no group " << group;
      }
      // No default printed with binary noise (0.10000000000000001 and the like).
      EXPECT_FALSE(std::regex_search(run.out, std::regex(R"(\d\.\d*0000000\d)"))) << run.out;
      EXPECT_FALSE(std::regex_search(run.out, std::regex(R"(\d\.\d*9999999\d)"))) << run.out;
    }
  }
}

TEST(ToolHelpTest, DefaultsAsPeopleWriteThem) {
  ScratchDir scratch;
  const ToolRun depth = RunTool(ToolPath("corridor_depth"), {"--help"}, scratch);
  // tool_flags.cc's defaults: 0.10 for --max_ceiling_disagreement, 40.0 for --max_range.
  EXPECT_NE(depth.out.find("(default: 0.1)"), std::string::npos) << depth.out;
  EXPECT_NE(depth.out.find("(default: 40)"), std::string::npos) << depth.out;
  EXPECT_NE(depth.out.find("(default: \"joint\")"), std::string::npos) << depth.out;
  // The solver's help names the default solver among the choices.
  const size_t solver = depth.out.find("--solver=");
  ASSERT_NE(solver, std::string::npos);
  EXPECT_NE(depth.out.find("joint", solver), std::string::npos);
}

TEST(ToolHelpTest, VersionPrintsVersionAndCommit) {
  ScratchDir scratch;
  for (const auto& tool : Tools()) {
    const ToolRun run = RunTool(ToolPath(tool.name), {"--version"}, scratch);
    EXPECT_EQ(run.exit_code, 0) << tool.name;
    EXPECT_TRUE(std::regex_search(
        run.out, std::regex(std::string("^") + tool.name +
                            R"( \d+\.\d+\.\d+ \(commit ([0-9a-f]{4,40}|unknown)\)\n$)")))
        << run.out;
  }
}

TEST(ToolHelpTest, UnknownFlagIsBadUsage) {
  ScratchDir scratch;
  for (const auto& tool : Tools()) {
    const ToolRun run = RunTool(ToolPath(tool.name), {"--no_such_flag=1"}, scratch);
    EXPECT_EQ(run.exit_code, 2) << tool.name << "\n"
                                << run.err;
    EXPECT_NE(run.err.find("no_such_flag"), std::string::npos) << run.err;
  }
}

// The old name warns and acts as the new one: the camera written is the same, and differs from
// the default field of view's.
TEST(ToolHelpTest, SynthOldHfovNameWarnsAndWorks) {
  ScratchDir scratch;
  const std::vector<std::string> common = {"--preset=single", "--width_px=64", "--height_px=48"};
  std::vector<std::string> old_args = common, new_args = common, default_args = common;
  old_args.push_back("--hfov_deg=70");
  old_args.push_back("--output_dir=" + scratch.Path("old"));
  new_args.push_back("--hfov=70");
  new_args.push_back("--output_dir=" + scratch.Path("new"));
  default_args.push_back("--output_dir=" + scratch.Path("default"));
  const ToolRun old_run = RunTool(ToolPath("corridor_synth"), old_args, scratch);
  const ToolRun new_run = RunTool(ToolPath("corridor_synth"), new_args, scratch);
  const ToolRun default_run = RunTool(ToolPath("corridor_synth"), default_args, scratch);
  ASSERT_EQ(old_run.exit_code, 0) << old_run.err;
  ASSERT_EQ(new_run.exit_code, 0) << new_run.err;
  ASSERT_EQ(default_run.exit_code, 0) << default_run.err;
  EXPECT_NE(old_run.err.find("--hfov_deg"), std::string::npos) << old_run.err;
  EXPECT_EQ(new_run.err.find("--hfov_deg"), std::string::npos) << new_run.err;
  const std::string old_camera = testing_util::ReadAll(scratch.Path("old/corridor/camera.yaml"));
  const std::string new_camera = testing_util::ReadAll(scratch.Path("new/corridor/camera.yaml"));
  const std::string default_camera =
      testing_util::ReadAll(scratch.Path("default/corridor/camera.yaml"));
  ASSERT_FALSE(old_camera.empty());
  EXPECT_EQ(old_camera, new_camera);
  EXPECT_NE(old_camera, default_camera);
  // Both names at once, with different values, is bad usage.
  std::vector<std::string> both = new_args;
  both.push_back("--hfov_deg=50");
  EXPECT_EQ(RunTool(ToolPath("corridor_synth"), both, scratch).exit_code, 2);
}

}  // namespace
}  // namespace corridor
