#pragma once

// Helpers of the reliability tests: a fresh folder per test, bad files written byte by byte, and
// the command-line tools run as child processes (posix_spawn) with their exit code, the signal
// that killed them if any, and their stderr.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/camera_yaml.h"
#include "tests/io/test_dir.h"  // ReadAll, Contains
#include "tests/reliability/corridor_image.h"

extern char** environ;

namespace corridor {
namespace testing_util {

const std::string kDepthTool = CORRIDOR_BINARY_DIR "/tools/corridor_depth";
const std::string kEvalTool = CORRIDOR_BINARY_DIR "/tools/corridor_eval";

// A fresh folder per test under ::testing::TempDir(), removed when the test ends.
class ScratchDir {
 public:
  ScratchDir() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("corridor_rel_") + info->test_suite_name() + "_" +
                       info->name() + "_" + std::to_string(::getpid());
    for (char& c : name) {
      if (c == '/') c = '_';  // Parameterised test names.
    }
    root_ = std::filesystem::path(::testing::TempDir()) / name;
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::string Path(const std::string& relative) const { return (root_ / relative).string(); }

  // Writes raw bytes to <root>/<relative>, creating folders; returns the full path.
  std::string Write(const std::string& relative, const std::string& bytes) const {
    const std::filesystem::path p = root_ / relative;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }

  // Writes an image with OpenCV (not the library's writer); returns the full path.
  std::string WriteImage(const std::string& relative, const cv::Mat& image) const {
    const std::filesystem::path p = root_ / relative;
    std::filesystem::create_directories(p.parent_path());
    EXPECT_TRUE(cv::imwrite(p.string(), image)) << p;
    return p.string();
  }

  // Writes a camera.yaml; returns the full path.
  std::string WriteCamera(const std::string& relative, const Camera& camera) const {
    const std::filesystem::path p = root_ / relative;
    EXPECT_TRUE(WriteCameraYaml(p.string(), camera).ok()) << p;
    return p.string();
  }

 private:
  std::filesystem::path root_;
};

inline bool Exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

// Files under a folder (recursively), hidden ones included; empty when it does not exist.
inline std::vector<std::string> ListFiles(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir, ec)) {
    if (entry.is_regular_file()) files.push_back(entry.path().string());
  }
  return files;
}

// How a child process ended.
struct ToolRun {
  bool started = false;
  bool signaled = false;  // Killed by a signal (a crash): never acceptable.
  int signal = 0;
  int exit_code = -1;
  std::string err;  // Its stderr.
  std::string out;  // Its stdout.
};

// Runs `binary` with `args` (no shell), stdout and stderr captured in files under `scratch`.
inline ToolRun RunTool(const std::string& binary, const std::vector<std::string>& args,
                       const ScratchDir& scratch) {
  static int counter = 0;
  const std::string tag = std::to_string(counter++);
  const std::string out_path = scratch.Path("run" + tag + ".out");
  const std::string err_path = scratch.Path("run" + tag + ".err");
  std::vector<std::string> all = {binary};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ToolRun run;
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return run;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return run;
  run.started = true;
  run.signaled = WIFSIGNALED(status);
  run.signal = run.signaled ? WTERMSIG(status) : 0;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = ReadAll(out_path);
  run.err = ReadAll(err_path);
  return run;
}

// corridor_depth --input=... --output_dir=... plus `extra` flags.
inline ToolRun RunDepthTool(const std::string& input, const std::string& output_dir,
                            const ScratchDir& scratch, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"--input=" + input, "--output_dir=" + output_dir};
  args.insert(args.end(), extra.begin(), extra.end());
  return RunTool(kDepthTool, args, scratch);
}

// Expects a clean exit with `code` whose stderr names every one of `names`.
inline void ExpectCleanExit(const ToolRun& run, int code, const std::vector<std::string>& names) {
  ASSERT_TRUE(run.started) << "could not start the tool";
  // For docs/reliability.md: the exit code and the message, in the test log.
  std::printf("[ tool     ] exit %d: %s\n", run.exit_code,
              run.err.substr(0, run.err.find('\n', run.err.find_first_not_of('\n'))).c_str());
  EXPECT_FALSE(run.signaled) << "killed by signal " << run.signal << "; stderr:\n"
                             << run.err;
  EXPECT_EQ(run.exit_code, code) << "stderr:\n"
                                 << run.err;
  for (const auto& name : names) {
    EXPECT_TRUE(Contains(run.err, name)) << "stderr does not name '" << name << "':\n"
                                         << run.err;
  }
}

}  // namespace testing_util
}  // namespace corridor
