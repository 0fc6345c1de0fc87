#include "tools/eval/report_writers.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <sstream>

#include "tests/evaluation/eval_test_records.h"

namespace corridor {
namespace {

using testing_util::Frames;

std::vector<EvalReport> Reports() { return {BuildReport(Frames(), {1.5, 2.0}, "grid", "paper")}; }

// Splits CSV text into rows of fields (quoted fields may hold commas and quotes).
std::vector<std::vector<std::string>> ParseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field);
      field.clear();
    } else if (c == '\n') {
      rows.back().push_back(field);
      field.clear();
      rows.emplace_back();
    } else {
      field += c;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

TEST(JsonString, EscapesEverythingJsonRequires) {
  EXPECT_EQ(JsonString("plain"), "\"plain\"");
  EXPECT_EQ(JsonString("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(JsonString("line\nnext\ttab\r"), "\"line\\nnext\\ttab\\r\"");
  EXPECT_EQ(JsonString(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
  EXPECT_EQ(JsonString("Gänge"), "\"Gänge\"");  // UTF-8 passes through.
}

TEST(JsonNumber, NonFiniteIsNull) {
  EXPECT_EQ(JsonNumber(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(JsonNumber(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(JsonNumber(0.1), "0.1");
  EXPECT_EQ(JsonNumber(-2.5e-7), "-2.5e-07");
  EXPECT_EQ(JsonNumber(40), "40");
}

TEST(ReportJson, ParsesAndHoldsTheNumbersAtTheDocumentedKeys) {
  ReportContext context;
  context.dataset = "/data/set \"one\"";
  const YAML::Node root = YAML::Load(ReportJson(Reports(), context));  // JSON is YAML.
  EXPECT_EQ(root["dataset"].as<std::string>(), "/data/set \"one\"");
  EXPECT_EQ(root["solver"].as<std::string>(), "grid");
  EXPECT_EQ(root["cap_keys"][1].as<std::string>(), "lt2");
  EXPECT_NEAR(root["scenes"]["Cord_E01"]["lt1p5"]["abs_rel"].as<double>(), 0.15, 1e-12);
  EXPECT_NEAR(root["scenes"]["Cord_E01"]["lt2"]["rmse"].as<double>(), 0.45, 1e-12);
  EXPECT_EQ(root["scenes"]["Cord_E01"]["difficulty"].as<std::string>(), "easy");
  EXPECT_NEAR(root["scenes"]["Cord_H01"]["width"]["rel_error"].as<double>(), 0.1, 1e-12);
  EXPECT_NEAR(root["all"]["lt1p5"]["abs_rel"].as<double>(), 0.7 / 3, 1e-12);
  EXPECT_NEAR(root["all"]["lt1p5"]["coverage"].as<double>(), 0.475, 1e-12);
  EXPECT_EQ(root["all"]["lt1p5"]["num_images"].as<int>(), 4);
  EXPECT_NEAR(root["all"]["timing"]["total"]["p90_s"].as<double>(), 0.037, 1e-12);
  EXPECT_TRUE(root["all"]["width"]["estimated"].IsNull());  // NaN -> null.
  EXPECT_NEAR(root["easy"]["lt2"]["abs_rel"].as<double>(), 0.15, 1e-12);
  EXPECT_TRUE(root["hard"].IsMap());
  EXPECT_EQ(root["failures"].size(), 1u);
  EXPECT_EQ(root["failures"][0]["frame"].as<std::string>(), "001");
  ASSERT_EQ(root["frames"].size(), 4u);
  EXPECT_TRUE(root["frames"][3]["estimate"].IsNull());
  EXPECT_NEAR(root["frames"][1]["truth"]["width"].as<double>(), 2.1, 1e-12);
  EXPECT_NEAR(root["abs_rel_by_depth"][1]["abs_rel"].as<double>(), 0.3, 1e-12);
  EXPECT_FALSE(root["configs"]);  // One configuration only.
}

TEST(ReportJson, EscapesSceneNamesUsedAsKeys) {
  std::vector<FrameRecord> frames = Frames();
  for (auto& f : frames) f.scene = "odd \"scene\"\\\n";
  const YAML::Node root =
      YAML::Load(ReportJson({BuildReport(frames, {1.5, 2.0}, "grid", "paper")}, {}));
  EXPECT_TRUE(root["scenes"]["odd \"scene\"\\\n"].IsMap());
}

TEST(ReportJson, CompareKeepsTheFirstConfigurationAtTheTop) {
  std::vector<FrameRecord> other = Frames();
  for (auto& f : other) {
    for (auto& m : f.metrics) m.abs_rel *= 2;
  }
  const std::vector<EvalReport> reports = {BuildReport(Frames(), {1.5, 2.0}, "grid", "paper"),
                                           BuildReport(other, {1.5, 2.0}, "lm", "exact")};
  const YAML::Node root = YAML::Load(ReportJson(reports, {}));
  EXPECT_NEAR(root["all"]["lt1p5"]["abs_rel"].as<double>(), 0.7 / 3, 1e-12);
  EXPECT_NEAR(root["configs"]["grid:paper"]["all"]["lt1p5"]["abs_rel"].as<double>(), 0.7 / 3,
              1e-12);
  EXPECT_NEAR(root["configs"]["lm:exact"]["all"]["lt1p5"]["abs_rel"].as<double>(), 1.4 / 3, 1e-12);
  EXPECT_EQ(root["config_order"][1].as<std::string>(), "lm:exact");
}

TEST(ReportCsv, OneRowPerFrameWithEveryMetric) {
  std::vector<FrameRecord> frames = Frames();
  frames[3].status = Status::NoCorridorFound("no lines, \"really\"");
  const auto rows = ParseCsv(ReportCsv({BuildReport(frames, {1.5, 2.0}, "grid", "paper")}));
  ASSERT_EQ(rows.size(), 5u);
  const auto& header = rows[0];
  for (const auto& row : rows) EXPECT_EQ(row.size(), header.size());
  auto column = [&](const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return size_t{0};
  };
  EXPECT_EQ(rows[1][column("config")], "grid:paper");
  EXPECT_EQ(rows[1][column("scene")], "Cord_E01");
  EXPECT_EQ(rows[1][column("status")], "ok");
  EXPECT_DOUBLE_EQ(std::stod(rows[1][column("lt1p5_abs_rel")]), 0.1);
  EXPECT_DOUBLE_EQ(std::stod(rows[2][column("est_width")]), 2.3);
  EXPECT_DOUBLE_EQ(std::stod(rows[2][column("true_width")]), 2.1);
  EXPECT_DOUBLE_EQ(std::stod(rows[3][column("lt2_coverage")]), 0.5);
  EXPECT_DOUBLE_EQ(std::stod(rows[3][column("t_total_s")]), 0.02);
  // No corridor found: the frame was read but refused (StatusClass).
  EXPECT_EQ(rows[4][column("status")], "refused");
  EXPECT_NE(rows[4][column("reason")].find("no lines, \"really\""), std::string::npos);
  EXPECT_EQ(rows[4][column("lt2_abs_rel")], "");  // NaN -> empty.
  EXPECT_EQ(rows[4][column("est_width")], "");
  EXPECT_DOUBLE_EQ(std::stod(rows[4][column("lt2_coverage")]), 0.0);
  for (const char* name : {"lt2_rmse_log10", "lt2_rmse_log", "lt2_delta3", "lt2_num_gt",
                           "t_perception_s", "t_solve_s", "t_rasterize_s", "width_rel_error"}) {
    column(name);
  }
}

TEST(ReportMarkdown, PaperLayout) {
  ReportContext context;
  context.dataset = "d";
  context.plot_files = {"plots/scene_abs_rel.png"};
  const std::string md = ReportMarkdown(Reports(), context);
  EXPECT_NE(md.find("## Table 1: Accuracy of corridor width estimation"), std::string::npos);
  EXPECT_NE(md.find("## Table 2: Accuracy of depth estimation, depth < 1.5 m"), std::string::npos);
  EXPECT_NE(md.find("## Table 3: Accuracy of depth estimation, depth < 2 m"), std::string::npos);
  EXPECT_NE(md.find("| Scene | AbsRel | Log10 | RMSE | RMSElog | RMSElog (ln) | SqRel |"),
            std::string::npos);
  EXPECT_NE(md.find("| Cord_E01 | 0.15000 |"), std::string::npos);
  EXPECT_NE(md.find("| **all** | 0.23333 |"), std::string::npos);
  EXPECT_NE(md.find("| Cord_E01 | 2.15 | 2.10 | 2.3810 |"), std::string::npos);
  EXPECT_NE(md.find("no lines"), std::string::npos);  // The failure is listed.
  EXPECT_NE(md.find("![plots/scene_abs_rel.png](plots/scene_abs_rel.png)"), std::string::npos);
  EXPECT_EQ(md.find("Comparison"), std::string::npos);
}

TEST(ReportMarkdown, CompareTable) {
  const std::vector<EvalReport> reports = {BuildReport(Frames(), {1.5, 2.0}, "grid", "paper"),
                                           BuildReport(Frames(), {1.5, 2.0}, "lm", "exact")};
  const std::string md = ReportMarkdown(reports, {});
  EXPECT_NE(md.find("Comparison of configurations"), std::string::npos);
  EXPECT_NE(md.find("| lm:exact | depth < 1.5 m | 0.23333 |"), std::string::npos);
  EXPECT_NE(md.find("| grid:paper | depth < 2 m | 0.23333 |"), std::string::npos);
}

}  // namespace
}  // namespace corridor
