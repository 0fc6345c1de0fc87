#include "tools/tool_help.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <map>

#include <gflags/gflags.h>
#include <glog/logging.h>

#ifndef CORRIDOR_VERSION
#define CORRIDOR_VERSION "unknown"
#endif
#ifndef CORRIDOR_GIT_COMMIT
#define CORRIDOR_GIT_COMMIT "unknown"
#endif

namespace corridor {
namespace {

constexpr int kLineWidth = 100;
constexpr int kIndent = 8;  // Where a flag's description starts, on the lines below its name.

const char* GroupTitle(FlagGroup group) {
  switch (group) {
    case FlagGroup::kInput:
      return "Input";
    case FlagGroup::kCamera:
      return "Camera";
    case FlagGroup::kSolver:
      return "Solver and depth";
    case FlagGroup::kOutput:
      return "Output";
    case FlagGroup::kAdvanced:
      return "Advanced";
  }
  return "Advanced";
}

// The groups of the flags that a tool does not place itself, in the order --help lists them
// (flags not listed here: kAdvanced, after the listed ones, by name).
const std::vector<std::pair<std::string, FlagGroup>>& FlagTable() {
  static const std::vector<std::pair<std::string, FlagGroup>> table = {
      {"input", FlagGroup::kInput},
      {"dataset", FlagGroup::kInput},
      {"labels", FlagGroup::kInput},
      {"image_topic", FlagGroup::kInput},
      {"camera_info_topic", FlagGroup::kInput},
      {"sequence", FlagGroup::kInput},
      {"skip_existing", FlagGroup::kInput},
      {"preset", FlagGroup::kInput},
      {"scene_name", FlagGroup::kInput},
      {"frames", FlagGroup::kInput},
      {"camera", FlagGroup::kCamera},
      {"fx", FlagGroup::kCamera},
      {"fy", FlagGroup::kCamera},
      {"cx", FlagGroup::kCamera},
      {"cy", FlagGroup::kCamera},
      {"hfov", FlagGroup::kCamera},
      {"focal", FlagGroup::kCamera},
      {"camera_height", FlagGroup::kCamera},
      {"width_px", FlagGroup::kCamera},
      {"height_px", FlagGroup::kCamera},
      {"pitch", FlagGroup::kCamera},
      {"yaw", FlagGroup::kCamera},
      {"offset", FlagGroup::kCamera},
      {"distance", FlagGroup::kCamera},
      {"solver", FlagGroup::kSolver},
      {"solvers", FlagGroup::kSolver},
      {"rasterizer", FlagGroup::kSolver},
      {"compare", FlagGroup::kSolver},
      {"loss", FlagGroup::kSolver},
      {"loss_scale", FlagGroup::kSolver},
      {"min_confidence", FlagGroup::kSolver},
      {"min_corridor_width", FlagGroup::kSolver},
      {"max_corridor_width", FlagGroup::kSolver},
      {"max_range", FlagGroup::kSolver},
      {"max_height", FlagGroup::kSolver},
      {"ceiling_height", FlagGroup::kSolver},
      {"width_prior", FlagGroup::kSolver},
      {"end_wall", FlagGroup::kSolver},
      {"output_dir", FlagGroup::kOutput},
      {"output_bag", FlagGroup::kOutput},
      {"write_vis", FlagGroup::kOutput},
      {"write_depth", FlagGroup::kOutput},
      {"write_floor_mask", FlagGroup::kOutput},
      {"write_model_fit", FlagGroup::kOutput},
      {"tile_width", FlagGroup::kOutput},
      {"write_model_fit", FlagGroup::kOutput},
      {"write_cloud", FlagGroup::kOutput},
      {"vis_max_depth", FlagGroup::kOutput},
      {"vis_max_error", FlagGroup::kOutput},
      {"caps", FlagGroup::kOutput},
  };
  return table;
}

// A flag's place in FlagTable(), or its size when it is not listed.
size_t FlagRank(const std::string& name) {
  const auto& table = FlagTable();
  for (size_t i = 0; i < table.size(); ++i) {
    if (table[i].first == name) return i;
  }
  return table.size();
}

FlagGroup DefaultFlagGroup(const std::string& name) {
  const size_t rank = FlagRank(name);
  return rank < FlagTable().size() ? FlagTable()[rank].second : FlagGroup::kAdvanced;
}

std::string BaseName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool IsOwnFlag(const ToolInfo& info, const gflags::CommandLineFlagInfo& flag) {
  for (const auto& [old_name, new_name] : info.aliases) {
    if (flag.name == old_name) return false;
  }
  const std::string file = BaseName(flag.filename);
  for (const auto& own : info.flag_files) {
    if (file == own) return true;
  }
  return false;
}

// The default as it would be typed: doubles shortest, strings quoted, "" left out.
std::string DefaultText(const gflags::CommandLineFlagInfo& flag) {
  const std::string& value = flag.default_value;
  if (flag.type == "double") return FormatFlagDouble(std::strtod(value.c_str(), nullptr));
  if (flag.type == "string") return value.empty() ? "" : "\"" + value + "\"";
  return value;
}

std::string Placeholder(const gflags::CommandLineFlagInfo& flag) {
  if (flag.type == "bool") return "";
  if (flag.type == "double") return "=X";
  if (flag.type == "string") return "=TEXT";
  return "=N";
}

// Appends `text` wrapped at kLineWidth, every line indented by `indent` spaces.
void AppendWrapped(const std::string& text, int indent, std::string* out) {
  const std::string pad(static_cast<size_t>(indent), ' ');
  std::string line;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find(' ', begin);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(begin, end - begin);
    if (!line.empty() && static_cast<int>(indent + line.size() + 1 + word.size()) > kLineWidth) {
      *out += pad + line + "\n";
      line.clear();
    }
    if (!word.empty()) line += (line.empty() ? "" : " ") + word;
    begin = end + 1;
  }
  if (!line.empty()) *out += pad + line + "\n";
}

}  // namespace

const char* ProjectVersion() { return CORRIDOR_VERSION; }
const char* BuildCommit() { return CORRIDOR_GIT_COMMIT; }

std::string FormatFlagDouble(double value) {
  char text[64];
  // At least the integer part's digits, so that 40 prints as 40, not 4e+01.
  const double magnitude = std::fabs(value);
  const int digits =
      magnitude >= 1 && magnitude < 1e15 ? static_cast<int>(std::log10(magnitude)) + 1 : 1;
  for (int precision = digits; precision <= 17; ++precision) {
    std::snprintf(text, sizeof(text), "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

std::string ToolHelpText(const ToolInfo& info) {
  std::map<std::string, FlagGroup> placed;
  for (const auto& [name, group] : info.groups) placed[name] = group;
  std::map<FlagGroup, std::vector<gflags::CommandLineFlagInfo>> grouped;
  std::vector<gflags::CommandLineFlagInfo> all;
  gflags::GetAllFlags(&all);  // Sorted by name.
  for (const auto& flag : all) {
    if (!IsOwnFlag(info, flag)) continue;
    const auto it = placed.find(flag.name);
    grouped[it != placed.end() ? it->second : DefaultFlagGroup(flag.name)].push_back(flag);
  }
  std::string out = info.name + ": " + info.summary + "\n\nUsage:\n";
  size_t begin = 0;
  while (begin < info.usage.size()) {
    size_t end = info.usage.find('\n', begin);
    if (end == std::string::npos) end = info.usage.size();
    out += "  " + info.usage.substr(begin, end - begin) + "\n";
    begin = end + 1;
  }
  for (auto& [group, flags] : grouped) {
    std::stable_sort(flags.begin(), flags.end(), [](const auto& a, const auto& b) {
      return FlagRank(a.name) < FlagRank(b.name);
    });
    out += "\n" + std::string(GroupTitle(group)) + ":\n";
    for (const auto& flag : flags) {
      out += "  --" + std::string(flag.type == "bool" ? "[no]" : "") + flag.name +
             Placeholder(flag) + "\n";
      std::string text = flag.description;
      const std::string default_text = DefaultText(flag);
      if (!default_text.empty()) text += " (default: " + default_text + ")";
      for (const auto& [old_name, new_name] : info.aliases) {
        if (new_name == flag.name) text += " (old name: --" + old_name + ")";
      }
      AppendWrapped(text, kIndent, &out);
    }
  }
  out += "\n";
  if (!info.notes.empty()) {
    AppendWrapped(info.notes, 0, &out);
    out += "\n";
  }
  AppendWrapped(
      "-h, --help: this text. --version: the version and the commit it was built from. "
      "--helpfull: every flag, the logging library's included (e.g. --v=1 logs more "
      "detail on stderr).",
      0, &out);
  return out;
}

Status CheckFlagNames(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg.size() < 2 || arg[0] != '-') continue;  // A positional argument: the tool says so.
    std::string name = arg.substr(arg[1] == '-' ? 2 : 1);
    name = name.substr(0, name.find('='));
    gflags::CommandLineFlagInfo info;
    if (gflags::GetCommandLineFlagInfo(name.c_str(), &info)) continue;
    if (name.rfind("no", 0) == 0 && gflags::GetCommandLineFlagInfo(name.c_str() + 2, &info) &&
        info.type == "bool") {
      continue;
    }
    return Status::InvalidArgument("unknown flag '" + arg + "' (see --help)");
  }
  return Status::Ok();
}

bool ParseToolFlags(const ToolInfo& info, int* argc, char*** argv, int* exit_code) {
  *exit_code = 0;
  for (int i = 1; i < *argc; ++i) {
    const std::string arg = (*argv)[i];
    if (arg == "--") break;
    if (arg == "-h" || arg == "--help" || arg == "-help") {
      std::fputs(ToolHelpText(info).c_str(), stdout);
      return false;
    }
    if (arg == "--version" || arg == "-version") {
      std::printf("%s %s (commit %s)\n", info.name.c_str(), ProjectVersion(), BuildCommit());
      return false;
    }
    if (arg == "--helpfull" || arg == "-helpfull") {
      gflags::SetUsageMessage(info.summary);
      gflags::ShowUsageWithFlags((*argv)[0]);
      return false;
    }
  }
  const Status names = CheckFlagNames(*argc, *argv);
  if (!names.ok()) {
    std::fprintf(stderr, "%s: %s\n", info.name.c_str(), names.message().c_str());
    *exit_code = 2;
    return false;
  }
  // glog writes to stderr, not to files under /tmp, and without its prefix: the tools' messages
  // are for people. --logtostderr=false or --log_prefix give glog's usual behaviour back.
  gflags::SetCommandLineOptionWithMode("logtostderr", "true", gflags::SET_FLAGS_DEFAULT);
  gflags::SetCommandLineOptionWithMode("log_prefix", "false", gflags::SET_FLAGS_DEFAULT);
  gflags::SetUsageMessage(info.summary);
  gflags::SetVersionString(std::string(ProjectVersion()) + " (commit " + BuildCommit() + ")");
  gflags::ParseCommandLineFlags(argc, argv, true);
  google::InitGoogleLogging((*argv)[0]);
  for (const auto& [old_name, new_name] : info.aliases) {
    gflags::CommandLineFlagInfo old_flag, new_flag;
    if (!gflags::GetCommandLineFlagInfo(old_name.c_str(), &old_flag) || old_flag.is_default) {
      continue;
    }
    CHECK(gflags::GetCommandLineFlagInfo(new_name.c_str(), &new_flag)) << new_name;
    if (!new_flag.is_default && new_flag.current_value != old_flag.current_value) {
      std::fprintf(stderr, "%s: --%s is the old name of --%s: give one of them\n",
                   info.name.c_str(), old_name.c_str(), new_name.c_str());
      *exit_code = 2;
      return false;
    }
    LOG(WARNING) << info.name << ": warning: --" << old_name << " is now called --" << new_name
                 << "; the old name still works but will go";
    gflags::SetCommandLineOption(new_name.c_str(), old_flag.current_value.c_str());
  }
  return true;
}

}  // namespace corridor
