// The library's evaluation (LoadDataset, EvaluateScenes, BuildReport) and the corridor_eval binary
// on the same generated dataset: the binary's report.json and report.csv must print the numbers
// the library computes, to their printed precision. The binary is an independent entry point
// (flags, ResolveInput, its writers); research code that calls the library must get its numbers.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "corridor_depth/evaluation.h"
#include "corridor_depth/dataset.h"
#include "synth/presets.h"
#include "tests/evaluation/eval_test_dataset.h"

namespace corridor {
namespace {

const std::string kBinary = CORRIDOR_BINARY_DIR "/tools/corridor_eval";

// A number as report.json prints it (%.15g, null when not finite).
std::string Json(double value) {
  if (!std::isfinite(value)) return "null";
  char text[40];
  std::snprintf(text, sizeof(text), "%.15g", value);
  return text;
}

// A number as report.csv prints it (%.10g, empty when not finite).
std::string Csv(double value) {
  if (!std::isfinite(value)) return "";
  char text[40];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

// One CSV line split into fields (RFC 4180 quoting: "" inside quotes is a quote).
std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// report.csv as rows of column name -> text.
std::vector<std::map<std::string, std::string>> ReadCsv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::map<std::string, std::string>> rows;
  if (!std::getline(in, line)) return rows;
  const std::vector<std::string> header = SplitCsv(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = SplitCsv(line);
    EXPECT_EQ(fields.size(), header.size()) << line;
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < header.size() && i < fields.size(); ++i) row[header[i]] = fields[i];
    rows.push_back(row);
  }
  return rows;
}

// Two scenes of the paper preset, three frames each, and one unreadable image.
void MakeDataset(const std::string& root) {
  for (synth::ScenePreset preset : synth::PaperPreset()) {
    if (preset.name != "Cord_E02" && preset.name != "Cord_H01") continue;
    preset.poses = {preset.poses.at(2), preset.poses.at(5), preset.poses.at(10)};
    ASSERT_TRUE(synth::WriteScene(root, preset, nullptr).ok()) << preset.name;
  }
  std::ofstream(root + "/Cord_H01/rgb/000099.png", std::ios::trunc) << "broken";
}

// The group's numbers in report.json equal the library's.
void ExpectSameGroup(const YAML::Node& json, const GroupSummary& g,
                     const std::vector<double>& caps, const std::string& what) {
  ASSERT_TRUE(json.IsMap()) << what;
  EXPECT_EQ(json["num_frames"].as<int>(), g.num_frames) << what;
  EXPECT_EQ(json["num_failed"].as<int>(), g.num_failed) << what;
  EXPECT_EQ(json["num_depth_truth"].as<int>(), g.num_depth_truth) << what;
  EXPECT_EQ(json["width"]["rel_error"].as<std::string>(), Json(g.width.rel_error)) << what;
  EXPECT_EQ(json["width"]["estimated"].as<std::string>(), Json(g.width.estimated)) << what;
  EXPECT_EQ(json["width"]["num_gross"].as<int>(), g.width.num_gross) << what;
  EXPECT_EQ(json["pose"]["yaw_abs_error_rad"].as<std::string>(), Json(g.pose.yaw)) << what;
  EXPECT_EQ(json["ceiling"]["num_within_tolerance"].as<int>(), g.ceiling.num_within) << what;
  ASSERT_EQ(g.depth.size(), caps.size());
  for (size_t c = 0; c < caps.size(); ++c) {
    const YAML::Node m = json[CapKey(caps[c])];
    const std::string cap = what + " " + CapKey(caps[c]);
    ASSERT_TRUE(m.IsMap()) << cap;
    EXPECT_EQ(m["abs_rel"].as<std::string>(), Json(g.depth[c].abs_rel)) << cap;
    EXPECT_EQ(m["rmse"].as<std::string>(), Json(g.depth[c].rmse)) << cap;
    EXPECT_EQ(m["delta1"].as<std::string>(), Json(g.depth[c].delta1)) << cap;
    EXPECT_EQ(m["coverage"].as<std::string>(), Json(g.depth[c].coverage)) << cap;
    EXPECT_EQ(m["num_evaluated"].as<int64_t>(), g.depth[c].num_evaluated) << cap;
  }
}

TEST(EvalLibraryAgreement, ToolReportPrintsTheLibrarysNumbers) {
  testing_util::EvalTempDir dir("agreement");
  const std::string data = dir.Path("data");
  MakeDataset(data);
  const std::vector<double> caps = {5.0, 40.0};

  // The library, as research code calls it.
  std::vector<DatasetScene> dataset;
  ASSERT_TRUE(LoadDataset(data, &dataset).ok());
  std::vector<EvalScene> scenes;
  for (const DatasetScene& scene : dataset) scenes.push_back(EvalSceneFromDataset(scene));
  RecoverDepthOptions options;
  options.solver = "joint";
  options.rasterizer = "exact";
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
  FrameEvalOptions frame_options;
  frame_options.caps = caps;
  EvalRunOptions run_options;
  run_options.threads = 2;
  size_t last_done = 0, calls = 0;
  run_options.progress = [&](size_t done, size_t total) {
    EXPECT_EQ(total, 7u);
    EXPECT_EQ(done, last_done + 1);
    last_done = done;
    ++calls;
  };
  std::vector<FrameRecord> records;
  ASSERT_TRUE(EvaluateScenes(scenes, *recoverer, frame_options, run_options, &records).ok());
  EXPECT_EQ(calls, 7u);
  const EvalReport report = BuildReport(records, caps, options.solver, options.rasterizer);
  ASSERT_EQ(report.all.num_frames, 7);
  ASSERT_EQ(report.all.num_failed, 1);  // The broken file; the rendered frames must work.

  // The binary, on the same folder.
  const std::string out = dir.Path("out");
  const std::string command = kBinary + " --dataset=" + data + " --output_dir=" + out +
                              " --solver=joint --rasterizer=exact --caps=5,40 --threads=2" +
                              " --write_vis=false --write_depth=false >/dev/null 2>" +
                              dir.Path("stderr.txt");
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);  // Some frames failed.

  const YAML::Node json = YAML::LoadFile(out + "/report.json");
  EXPECT_EQ(json["num_frames"].as<int>(), 7);
  EXPECT_EQ(json["num_failed"].as<int>(), 1);
  ExpectSameGroup(json["all"], report.all, caps, "all");
  for (const GroupSummary& scene : report.scenes) {
    ExpectSameGroup(json["scenes"][scene.name], scene, caps, scene.name);
  }
  for (const GroupSummary& group : report.groups) {
    ExpectSameGroup(json[group.name], group, caps, group.name);
  }
  const YAML::Node failures = json["failures"];
  ASSERT_EQ(failures.size(), report.failures.size());
  for (size_t i = 0; i < report.failures.size(); ++i) {
    EXPECT_EQ(failures[i]["scene"].as<std::string>(), report.failures[i].scene);
    EXPECT_EQ(failures[i]["frame"].as<std::string>(), report.failures[i].frame);
    EXPECT_EQ(failures[i]["reason"].as<std::string>(), report.failures[i].reason);
  }
  EXPECT_EQ(report.failures.front().frame, "000099");

  // report.csv, frame by frame.
  const auto rows = ReadCsv(out + "/report.csv");
  ASSERT_EQ(rows.size(), records.size());
  for (size_t i = 0; i < records.size(); ++i) {
    const FrameRecord& r = records[i];
    auto row = rows[i];
    const std::string what = r.scene + "/" + r.frame;
    EXPECT_EQ(row["scene"], r.scene);
    EXPECT_EQ(row["frame"], r.frame);
    EXPECT_EQ(row["status"], StatusClass(r.status.code())) << what;
    EXPECT_EQ(row["est_width"], r.has_estimate ? Csv(r.estimate.width) : "") << what;
    EXPECT_EQ(row["est_yaw"], r.has_estimate ? Csv(r.estimate.yaw) : "") << what;
    EXPECT_EQ(row["true_width"], r.has_truth ? Csv(r.truth.width) : "") << what;
    EXPECT_EQ(row["confidence"], r.ran ? Csv(r.confidence) : "") << what;
    for (size_t c = 0; c < caps.size(); ++c) {
      const std::string key = CapKey(caps[c]);
      EXPECT_EQ(row[key + "_abs_rel"], Csv(r.metrics[c].abs_rel)) << what << " " << key;
      EXPECT_EQ(row[key + "_rmse"], Csv(r.metrics[c].rmse)) << what << " " << key;
      EXPECT_EQ(row[key + "_coverage"], Csv(r.metrics[c].coverage)) << what << " " << key;
    }
  }
}

}  // namespace
}  // namespace corridor
