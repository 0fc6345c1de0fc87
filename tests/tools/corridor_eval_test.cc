// Acceptance test of the corridor_eval binary: a small generated dataset in, the report out, and
// one frame's AbsRel recomputed by hand from the written PNGs.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>

#include "tests/evaluation/eval_test_dataset.h"

namespace corridor {
namespace {

using testing_util::EvalTempDir;
using testing_util::ReliabilityGeometry;

const std::string kBinary = CORRIDOR_BINARY_DIR "/tools/corridor_eval";

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs corridor_eval with `args`; returns the exit code and fills *err with its stderr.
int RunEval(const EvalTempDir& dir, const std::string& args, std::string* err) {
  const std::string err_path = dir.Path("stderr.txt");
  const std::string command = kBinary + " " + args + " >/dev/null 2>" + err_path;
  const int status = std::system(command.c_str());
  *err = ReadText(err_path);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Scene Cord_E01_z: three good frames. Cord_H01_z: one good, one unreadable, one whose depth
// image is smaller than its colour image.
void MakeDataset(const std::string& root) {
  testing_util::WriteEvalTestScene(
      root, "Cord_E01_z",
      {ReliabilityGeometry(0.05, 0.08, 0.1, 2.1), ReliabilityGeometry(-0.1, 0.05, -0.2, 2.1),
       ReliabilityGeometry(0.12, 0.1, 0.0, 2.1)});
  testing_util::WriteEvalTestScene(
      root, "Cord_H01_z",
      {ReliabilityGeometry(0.0, 0.06, 0.3, 3.0), ReliabilityGeometry(0.2, 0.09, -0.1, 3.0),
       ReliabilityGeometry(-0.05, 0.07, 0.1, 3.0)});
  std::ofstream(root + "/Cord_H01_z/rgb/001.png", std::ios::trunc) << "broken";
  cv::imwrite(root + "/Cord_H01_z/depth/002.png", cv::Mat(24, 32, CV_16U, cv::Scalar(3000)));
}

// AbsRel over 0 < gt <= cap where pred > 0, written out here rather than with the library.
double HandAbsRel(const cv::Mat& pred, const cv::Mat& gt, double cap, int* count) {
  double sum = 0;
  *count = 0;
  for (int v = 0; v < gt.rows; ++v) {
    for (int u = 0; u < gt.cols; ++u) {
      const double g = gt.at<float>(v, u), p = pred.at<float>(v, u);
      if (g <= 0 || g > cap || p <= 0) continue;
      sum += std::abs(g - p) / g;
      ++*count;
    }
  }
  return *count > 0 ? sum / *count : NAN;
}

TEST(CorridorEval, ReportMatchesAHandComputedAbsRel) {
  EvalTempDir dir("binary");
  MakeDataset(dir.Path("data"));
  std::string err;
  const int code = RunEval(dir,
                           "--dataset=" + dir.Path("data") + " --output_dir=" + dir.Path("out") +
                               " --solver=grid --rasterizer=paper --threads=2",
                           &err);
  EXPECT_EQ(code, 1) << err;  // Two frames fail.
  for (const char* file :
       {"report.md", "report.json", "report.csv", "index.html", "plots/abs_rel_by_depth.png",
        "plots/width_error_hist.png", "plots/scene_abs_rel.png", "vis/Cord_E01_z/000.png",
        "vis/Cord_H01_z/002.png", "depth/Cord_E01_z/002.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir.Path("out/") + file)) << file;
  }
  const YAML::Node root = YAML::LoadFile(dir.Path("out/report.json"));
  EXPECT_EQ(root["solver"].as<std::string>(), "grid");
  EXPECT_EQ(root["num_frames"].as<int>(), 6);
  EXPECT_EQ(root["num_failed"].as<int>(), 2);
  ASSERT_EQ(root["failures"].size(), 2u);
  EXPECT_NE(root["failures"][0]["reason"].as<std::string>().find("001.png"), std::string::npos);
  EXPECT_NE(root["failures"][1]["reason"].as<std::string>().find("colour image"),
            std::string::npos);

  // Frame Cord_E01_z/000 by hand, from the ground-truth PNG and the predicted depth PNG.
  const cv::Mat gt = testing_util::ReadMillimetrePng(dir.Path("data/Cord_E01_z/depth/000.png"));
  const cv::Mat pred = testing_util::ReadMillimetrePng(dir.Path("out/depth/Cord_E01_z/000.png"));
  ASSERT_FALSE(gt.empty());
  ASSERT_EQ(pred.size(), gt.size());
  const YAML::Node frame = root["frames"][0];
  ASSERT_EQ(frame["frame"].as<std::string>(), "000");
  ASSERT_EQ(frame["status"].as<std::string>(), "ok");
  for (const auto& [cap, key] : {std::pair<double, std::string>{5, "lt5"}, {40, "lt40"}}) {
    int count = 0;
    const double abs_rel = HandAbsRel(pred, gt, cap, &count);
    ASSERT_GT(count, 1000) << key;
    // The PNG holds millimetres: the prediction is rounded by at most 0.5 mm per pixel.
    EXPECT_NEAR(frame[key]["abs_rel"].as<double>(), abs_rel, 5e-4 + 1e-3 * abs_rel) << key;
    EXPECT_LT(abs_rel, 0.2) << key;
  }

  // The scene's AbsRel is the mean of its frames'; a failed frame counts with coverage 0.
  double sum = 0, coverage = 0;
  for (int i = 0; i < 3; ++i) sum += root["frames"][i]["lt5"]["abs_rel"].as<double>();
  EXPECT_NEAR(root["scenes"]["Cord_E01_z"]["lt5"]["abs_rel"].as<double>(), sum / 3, 1e-9);
  for (int i = 3; i < 6; ++i) coverage += root["frames"][i]["lt40"]["coverage"].as<double>();
  EXPECT_EQ(root["frames"][4]["lt40"]["coverage"].as<double>(), 0.0);
  EXPECT_NEAR(root["scenes"]["Cord_H01_z"]["lt40"]["coverage"].as<double>(), coverage / 3, 1e-9);
  EXPECT_TRUE(root["easy"].IsMap());
  EXPECT_TRUE(root["hard"].IsMap());
  EXPECT_NEAR(root["scenes"]["Cord_E01_z"]["width"]["truth"].as<double>(), 2.1, 1e-9);
  EXPECT_LT(root["scenes"]["Cord_E01_z"]["width"]["rel_error"].as<double>(), 0.1);

  const std::string md = ReadText(dir.Path("out/report.md"));
  EXPECT_NE(md.find("Table 2: Accuracy of depth estimation, depth < 5 m"), std::string::npos);
  const std::string csv = ReadText(dir.Path("out/report.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);  // Header and six frames.
}

TEST(CorridorEval, CompareWritesEachConfiguration) {
  EvalTempDir dir("binary");
  testing_util::WriteEvalTestScene(dir.Path("data"), "E1",
                                   {ReliabilityGeometry(0.05, 0.08, 0.1, 2.1)});
  std::string err;
  const int code = RunEval(dir,
                           "--dataset=" + dir.Path("data") + " --output_dir=" + dir.Path("out") +
                               " --compare=grid:paper,closed_form+lm:exact --caps=5 --threads=1",
                           &err);
  ASSERT_EQ(code, 0) << err;
  const YAML::Node root = YAML::LoadFile(dir.Path("out/report.json"));
  EXPECT_EQ(root["solver"].as<std::string>(), "grid");
  EXPECT_TRUE(root["configs"]["grid:paper"]["all"]["lt5"]["abs_rel"].IsScalar());
  EXPECT_TRUE(root["configs"]["closed_form+lm:exact"]["all"]["lt5"]["abs_rel"].IsScalar());
  EXPECT_EQ(root["all"]["lt5"]["abs_rel"].as<double>(),
            root["configs"]["grid:paper"]["all"]["lt5"]["abs_rel"].as<double>());
  EXPECT_FALSE(root["all"]["lt40"]);
  EXPECT_NE(ReadText(dir.Path("out/report.md")).find("Comparison of configurations"),
            std::string::npos);
}

TEST(CorridorEval, BadUsageExitsTwoWithAMessage) {
  EvalTempDir dir("binary");
  testing_util::WriteEvalTestScene(dir.Path("data"), "E1",
                                   {ReliabilityGeometry(0.05, 0.08, 0.1, 2.1)});
  const std::string io = " --dataset=" + dir.Path("data") + " --output_dir=" + dir.Path("out");
  std::string err;
  EXPECT_EQ(RunEval(dir, io + " --threads=-1", &err), 2);
  EXPECT_NE(err.find("--threads"), std::string::npos) << err;
  EXPECT_EQ(RunEval(dir, io + " --caps=5,abc", &err), 2);
  EXPECT_NE(err.find("'abc' is not a number"), std::string::npos) << err;
  EXPECT_EQ(RunEval(dir, io + " --solver=nonsense", &err), 2);
  EXPECT_NE(err.find("grid"), std::string::npos) << err;  // The valid names are listed.
  EXPECT_EQ(RunEval(dir, io + " --compare=grid", &err), 2);
  EXPECT_NE(err.find("solver:rasterizer"), std::string::npos) << err;
  EXPECT_EQ(RunEval(dir, "--output_dir=" + dir.Path("out"), &err), 2);
  EXPECT_NE(err.find("--dataset"), std::string::npos) << err;
  EXPECT_EQ(RunEval(dir, "--dataset=" + dir.Path("missing") + " --output_dir=x", &err), 2);

  // Every frame fails: the report is still written, and the exit code says nothing worked.
  std::ofstream(dir.Path("data/E1/rgb/000.png"), std::ios::trunc) << "broken";
  EXPECT_EQ(RunEval(dir, io, &err), 2);
  EXPECT_NE(err.find("no frame could be evaluated"), std::string::npos) << err;
  EXPECT_TRUE(std::filesystem::exists(dir.Path("out/report.json")));
}

}  // namespace
}  // namespace corridor
