#pragma once

#include <string>
#include <utility>
#include <vector>

#include "corridor_depth/status.h"

namespace corridor {

// The groups a tool's --help lists its flags in, in this order.
enum class FlagGroup { kInput,
                       kCamera,
                       kSolver,
                       kOutput,
                       kAdvanced };

// What a tool's --help and --version say about it.
struct ToolInfo {
  std::string name;     // "corridor_depth".
  std::string summary;  // One line: what the tool does.
  std::string usage;    // Example command lines, one per line, without indentation.
  std::string notes;    // Printed after the flags (exit codes, outputs); may be empty.
  // The source files (base names) whose DEFINE_* flags are the tool's own: its main file and
  // tool_flags.cc when it takes the depth-recovery flags. Other flags (glog's, gflags') are hidden.
  std::vector<std::string> flag_files;
  // Groups of flags whose group differs from the default table's (DefaultFlagGroup).
  std::vector<std::pair<std::string, FlagGroup>> groups;
  // Renamed flags: {old name, new name}. The old one is kept (defined by the tool), hidden from
  // --help except as a note beside the new one, and warns when given (ParseToolFlags).
  std::vector<std::pair<std::string, std::string>> aliases;
};

// The version of the project (CMake's project version) and the git commit it was built from
// ("unknown" when it was not built from a git checkout).
const char* ProjectVersion();
const char* BuildCommit();

// A double as people write it: the shortest text that reads back to the same value (0.1, 40,
// 1e-06).
std::string FormatFlagDouble(double value);

// The tool's help text: summary, usage, its own flags grouped, with defaults, and the notes.
std::string ToolHelpText(const ToolInfo& info);

// The flags of every tool start here. Handles --help, -h, --helpfull and --version (prints, and
// *exit_code = 0); rejects an unknown flag (*exit_code = 2, message on stderr); parses the flags
// (gflags), makes glog log to stderr without its line prefix unless asked otherwise, applies the
// aliases with a warning, and starts glog. Returns true when the tool should go on, false when it
// should return *exit_code. Positional arguments are left in argc/argv.
bool ParseToolFlags(const ToolInfo& info, int* argc, char*** argv, int* exit_code);

// An unknown flag is bad usage (the tools exit 2), but gflags itself would exit 1 on it.
// InvalidArgument naming the first unknown flag; "--" ends the flags; "--noNAME" is accepted for a
// boolean NAME.
Status CheckFlagNames(int argc, char** argv);

}  // namespace corridor
