// Nothing is lost: in a run over many frames a bad frame is reported and skipped while every good
// frame is written; outputs only ever appear complete under their final names (temporary name,
// then rename), even when the run is killed; --skip_existing resumes a run where it stopped,
// recomputing only the missing frames and keeping geometry.csv complete.

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <thread>

#include "io/file_util.h"
#include "corridor_depth/image_io.h"
#include "tests/reliability/reliability_util.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;
using testing_util::Contains;
using testing_util::ExpectCleanExit;
using testing_util::ListFiles;
using testing_util::ReadAll;
using testing_util::ReliabilityCamera;
using testing_util::ReliabilityGeometry;
using testing_util::RunDepthTool;
using testing_util::ScratchDir;

std::string FrameName(int i) {
  char name[16];
  std::snprintf(name, sizeof(name), "%03d", i);
  return name;
}

// <dir>/in/camera.yaml and frames 000..n-1 (two corridor poses alternating).
void WriteFrames(const ScratchDir& dir, int n) {
  const Camera camera = ReliabilityCamera();
  dir.WriteCamera("in/camera.yaml", camera);
  const cv::Mat poses[2] = {
      testing_util::RenderTestCorridor(camera, ReliabilityGeometry(0.05, 0.08, 0.1), 1),
      testing_util::RenderTestCorridor(camera, ReliabilityGeometry(-0.1, 0.06, -0.2), 2)};
  for (int i = 0; i < n; ++i) dir.WriteImage("in/" + FrameName(i) + ".png", poses[i % 2]);
}

// geometry.csv's lines after the header.
std::vector<std::string> CsvRows(const std::string& path) {
  std::vector<std::string> rows;
  std::istringstream in(ReadAll(path));
  std::string line;
  for (bool header = true; std::getline(in, line); header = false) {
    if (!header) rows.push_back(line);
  }
  return rows;
}

TEST(NothingLost, OneBadFrameIsReportedAndEveryGoodFrameWritten) {
  ScratchDir dir;
  WriteFrames(dir, 7);
  const std::string bad = dir.Write("in/003.png", "not a png at all");
  const auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir);
  ExpectCleanExit(run, 1, {bad, "not a readable image"});
  for (int i = 0; i < 7; ++i) {
    const std::string path = dir.Path("out/in/depth/" + FrameName(i) + ".png");
    EXPECT_EQ(testing_util::Exists(path), i != 3) << i;
    cv::Mat depth;
    if (i != 3) {
      EXPECT_TRUE(ReadDepthPng(path, &depth).ok()) << path;
    }
  }
  const std::vector<std::string> rows = CsvRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(rows.size(), 7u);
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(rows[i].rfind(FrameName(i) + ",", 0), 0u) << rows[i];
    EXPECT_EQ(Contains(rows[i], ",ok,"), i != 3) << rows[i];
  }
  EXPECT_TRUE(Contains(run.out, "6 of 7 frames ok")) << run.out;
}

TEST(NothingLost, TemporaryNamesAreHiddenSiblingsThatKeepTheExtension) {
  ScratchDir dir;
  const std::string final_path = dir.Path("a/b/frame.png");
  std::string tmp;
  ASSERT_TRUE(PrepareAtomicWrite(final_path, &tmp).ok());
  const fs::path t(tmp);
  EXPECT_EQ(t.parent_path(), fs::path(final_path).parent_path());
  EXPECT_EQ(t.filename().string()[0], '.');
  EXPECT_EQ(t.extension(), ".png");
  EXPECT_NE(t.filename(), fs::path(final_path).filename());
  std::string tmp2;
  ASSERT_TRUE(PrepareAtomicWrite(final_path, &tmp2).ok());
  EXPECT_NE(tmp, tmp2);  // Concurrent writers never share a temporary.
}

TEST(NothingLost, FailedWritesLeaveNoFinalFileAndNoTemporary) {
  ScratchDir dir;
  // The encoder fails (five channels): nothing under the final name, no temporary left behind.
  const std::string png = dir.Path("out/five.png");
  EXPECT_FALSE(WriteImageAtomic(png, cv::Mat(cv::Mat::zeros(8, 8, CV_8UC(5)))).ok());
  EXPECT_FALSE(testing_util::Exists(png));
  EXPECT_TRUE(ListFiles(dir.Path("out")).empty());
  // The rename fails (a folder has the final name): the temporary is removed.
  fs::create_directories(dir.Path("out/taken.csv"));
  const Status status = WriteTextAtomic(dir.Path("out/taken.csv"), "a,b\n");
  EXPECT_EQ(status.code(), StatusCode::kIoError);
  EXPECT_TRUE(Contains(status.message(), dir.Path("out/taken.csv"))) << status.ToString();
  EXPECT_TRUE(ListFiles(dir.Path("out")).empty());
  // A failed rewrite keeps the old file whole.
  const cv::Mat depth(6, 9, CV_32F, cv::Scalar(2.5f));
  ASSERT_TRUE(WriteDepthPng(dir.Path("out/d.png"), depth).ok());
  const std::string before = ReadAll(dir.Path("out/d.png"));
  const cv::Mat five_channels = cv::Mat::zeros(8, 8, CV_8UC(5));
  EXPECT_FALSE(WriteImageAtomic(dir.Path("out/d.png"), five_channels).ok());
  EXPECT_EQ(ReadAll(dir.Path("out/d.png")), before);
  EXPECT_EQ(ListFiles(dir.Path("out")).size(), 1u);
  // The parent cannot be created (a file is in the way).
  dir.Write("blocked", "x");
  EXPECT_EQ(WriteDepthPng(dir.Path("blocked/d.png"), depth).code(), StatusCode::kIoError);
}

// Starts corridor_depth without waiting; returns its pid.
pid_t Start(const ScratchDir& dir, const std::vector<std::string>& args) {
  std::vector<std::string> all = {testing_util::kDepthTool};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string log = dir.Path("killed.log");
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT, 0644);
  pid_t pid = -1;
  posix_spawn(&pid, all[0].c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Killed mid-run, a run leaves only complete files under final names; a rerun with
// --skip_existing finishes the job.
TEST(NothingLost, KilledRunLeavesOnlyCompleteFilesAndResumes) {
  ScratchDir dir;
  const int n = 40;
  WriteFrames(dir, n);
  const pid_t pid = Start(dir, {"--input=" + dir.Path("in"), "--output_dir=" + dir.Path("out")});
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (ListFiles(dir.Path("out/in/depth")).size() < 3 &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  for (const std::string& file : ListFiles(dir.Path("out"))) {
    const std::string name = fs::path(file).filename().string();
    if (name[0] == '.') continue;  // A temporary: never read by anyone.
    if (fs::path(file).extension() == ".png") {
      cv::Mat image;
      EXPECT_TRUE(ReadColorImage(file, &image).ok()) << file << " is not whole";
    }
  }
  const size_t done_before = ListFiles(dir.Path("out/in/depth")).size();
  const auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir, {"--skip_existing"});
  ExpectCleanExit(run, 0, {});
  for (int i = 0; i < n; ++i) {
    cv::Mat depth;
    EXPECT_TRUE(ReadDepthPng(dir.Path("out/in/depth/" + FrameName(i) + ".png"), &depth).ok()) << i;
  }
  const std::vector<std::string> rows = CsvRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(rows.size(), static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) EXPECT_EQ(rows[i].rfind(FrameName(i) + ",ok,", 0), 0u) << rows[i];
  RecordProperty("frames_done_before_kill", static_cast<int>(done_before));
}

TEST(NothingLost, SkipExistingRecomputesOnlyTheMissingFrames) {
  ScratchDir dir;
  const int n = 6;
  WriteFrames(dir, n);
  auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir);
  ExpectCleanExit(run, 0, {});
  const std::vector<std::string> first = CsvRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(first.size(), static_cast<size_t>(n));
  std::vector<fs::file_time_type> times;
  for (int i = 0; i < n; ++i) {
    times.push_back(fs::last_write_time(dir.Path("out/in/depth/" + FrameName(i) + ".png")));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // Rewrites get later times.
  const std::set<int> removed = {1, 4};
  for (int i : removed) fs::remove(dir.Path("out/in/depth/" + FrameName(i) + ".png"));

  run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir, {"--skip_existing"});
  ExpectCleanExit(run, 0, {});
  EXPECT_TRUE(Contains(run.out, "6 of 6 frames ok, 4 of them kept")) << run.out;
  const std::vector<std::string> second = CsvRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(second.size(), static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const std::string depth = dir.Path("out/in/depth/" + FrameName(i) + ".png");
    ASSERT_TRUE(testing_util::Exists(depth)) << i;
    EXPECT_EQ(second[i].rfind(FrameName(i) + ",ok,", 0), 0u) << second[i];
    if (removed.count(i)) {
      EXPECT_GT(fs::last_write_time(depth), times[i]) << i;
    } else {
      EXPECT_EQ(fs::last_write_time(depth), times[i]) << i << " was recomputed";
      EXPECT_EQ(second[i], first[i]);  // The row (with its time) is the first run's.
    }
  }

  // Every frame present: nothing to do, the CSV stays as it was.
  run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir, {"--skip_existing"});
  ExpectCleanExit(run, 0, {});
  EXPECT_TRUE(Contains(run.out, "6 of them kept")) << run.out;
  EXPECT_EQ(CsvRows(dir.Path("out/in/geometry.csv")), second);

  // A frame whose depth exists but whose row was lost is recomputed.
  std::string csv = ReadAll(dir.Path("out/in/geometry.csv"));
  csv.erase(csv.find(second[2]), second[2].size() + 1);
  dir.Write("out/in/geometry.csv", csv);
  run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir, {"--skip_existing"});
  ExpectCleanExit(run, 0, {});
  EXPECT_TRUE(Contains(run.out, "5 of them kept")) << run.out;
  EXPECT_EQ(CsvRows(dir.Path("out/in/geometry.csv")).size(), static_cast<size_t>(n));

  // A geometry.csv that is not one: exit 2, naming it.
  dir.Write("out/in/geometry.csv", "something else\n");
  run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir, {"--skip_existing"});
  ExpectCleanExit(run, 2, {dir.Path("out/in/geometry.csv"), "header"});
}

}  // namespace
}  // namespace corridor
