// The accuracy guard: the README's demo corridor (corridor_synth --preset=sequence --frames=12
// --seed=7) and a slice of the paper preset (frames 0, 7 and 14 of its nine scenes), rendered by
// the generator, recovered frame by frame with the default options and scored against the
// generator's truth (its width and ray-cast depth). Each set's mean width error, AbsRel < 5 m and
// refused frames may be at most 10% (relative) above tests/data/accuracy_baseline.csv: a change
// that makes them worse fails here, on purpose. The baseline moves only when results improve:
//   CORRIDOR_WRITE_ACCURACY_BASELINE=tests/data/accuracy_baseline.csv
//     build/tests/accuracy/accuracy_guard_test   (one command line)
// writes this run's figures there (then check the diff, and commit it only if no figure is worse).
// The demo itself: mean width error at most 2%, no frame more than 5% off.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/status.h"
#include "corridor_depth/depth_metrics.h"
#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"
#include "tests/support/demo_corridor.h"

namespace corridor {
namespace {

// One set's figures, as the baseline file holds them.
struct SetFigures {
  int frames = 0;
  int refused = 0;             // Frames whose status class is "refused".
  int failed = 0;              // ... "failed".
  double width_error = 0;      // Mean |w - w_true| / w_true over the frames ok.
  double max_width_error = 0;  // The largest of them.
  double abs_rel = 0;          // Mean AbsRel of the depth < 5 m over the frames ok.
};

constexpr double kCap = 5.0;     // AbsRel < 5 m, as corridor_eval reports it.
constexpr double kSlack = 0.10;  // Worse than the baseline by more than this (relative) fails.

// Renders each (preset, pose) and recovers it alone; the figures over all of them.
SetFigures Evaluate(const std::vector<std::pair<synth::ScenePreset, std::vector<size_t>>>& sets) {
  SetFigures figures;
  std::unique_ptr<DepthRecoverer> recoverer;
  EXPECT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  if (recoverer == nullptr) return figures;
  std::vector<double> width_errors;
  std::vector<DepthMetrics> depth;
  for (const auto& [preset, poses] : sets) {
    const synth::SceneOptions& scene = preset.scene;
    for (const size_t pose : poses) {
      synth::Frame frame;
      EXPECT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses.at(pose), &frame).ok());
      RecoverDepthResult result;
      recoverer->Recover(frame.bgr, preset.camera, &result);
      ++figures.frames;
      const std::string status = StatusClass(result.status.code());
      figures.refused += status == "refused";
      figures.failed += status == "failed";
      if (status != "ok") continue;
      width_errors.push_back(std::abs(RelativeError(result.geometry.width, frame.truth.width)));
      depth.push_back(ComputeDepthMetrics(result.depth, frame.depth, kCap));
    }
  }
  for (const double e : width_errors) {
    figures.width_error += e / width_errors.size();
    figures.max_width_error = std::max(figures.max_width_error, e);
  }
  figures.abs_rel = depth.empty() ? 0 : AverageDepthMetrics(depth).abs_rel;
  return figures;
}

// Every figure once per test binary: rendering and recovering take most of its time.
const std::map<std::string, SetFigures>& Figures() {
  static const std::map<std::string, SetFigures> figures = [] {
    std::map<std::string, SetFigures> all;
    const synth::ScenePreset demo = testing_util::DemoCorridor();
    std::vector<size_t> every;
    for (size_t i = 0; i < demo.poses.size(); ++i) every.push_back(i);
    all["demo"] = Evaluate({{demo, every}});
    std::vector<std::pair<synth::ScenePreset, std::vector<size_t>>> paper;
    for (const auto& preset : synth::PaperPreset()) paper.push_back({preset, {0, 7, 14}});
    all["paper_slice"] = Evaluate(paper);
    return all;
  }();
  return figures;
}

std::map<std::string, SetFigures> ReadBaseline(const std::string& path) {
  std::map<std::string, SetFigures> baseline;
  std::ifstream in(path);
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {  // set,frames,refused,failed,width_error,max_width_error,abs_rel_lt5m
      header = false;
      continue;
    }
    std::stringstream fields(line);
    std::string name, value;
    std::getline(fields, name, ',');
    std::vector<double> v;
    while (std::getline(fields, value, ',')) v.push_back(std::stod(value));
    if (v.size() != 6) {
      ADD_FAILURE() << path << ": malformed line '" << line << "'";
      continue;
    }
    SetFigures& f = baseline[name];
    f.frames = static_cast<int>(v[0]);
    f.refused = static_cast<int>(v[1]);
    f.failed = static_cast<int>(v[2]);
    f.width_error = v[3];
    f.max_width_error = v[4];
    f.abs_rel = v[5];
  }
  return baseline;
}

void WriteBaseline(const std::string& path, const std::map<std::string, SetFigures>& figures) {
  std::ofstream out(path);
  out << "# The accuracy guard's baseline (tests/accuracy/accuracy_guard_test.cc), written by\n"
         "#   CORRIDOR_WRITE_ACCURACY_BASELINE=tests/data/accuracy_baseline.csv "
         "build/tests/accuracy/accuracy_guard_test\n"
         "# Frame by frame, default options; width errors relative, AbsRel of the depth < 5 m.\n"
         "# Move it only when no figure gets worse.\n"
         "set,frames,refused,failed,width_error,max_width_error,abs_rel_lt5m\n";
  out.precision(6);
  for (const auto& [name, f] : figures) {
    out << name << "," << f.frames << "," << f.refused << "," << f.failed << ","
        << f.width_error << "," << f.max_width_error << "," << f.abs_rel << "\n";
  }
}

std::string BaselinePath() {
  return std::string(CORRIDOR_SOURCE_DIR) + "/tests/data/accuracy_baseline.csv";
}

// The figures of `now` worse than `base` by more than kSlack (relative), named; empty when none is.
std::vector<std::string> Regressions(const SetFigures& now, const SetFigures& base) {
  std::vector<std::string> worse;
  const auto check = [&](const char* name, double value, double baseline) {
    if (value > (1 + kSlack) * baseline) {
      worse.push_back(std::string(name) + " " + std::to_string(value) + " against " +
                      std::to_string(baseline));
    }
  };
  check("width_error", now.width_error, base.width_error);
  check("abs_rel_lt5m", now.abs_rel, base.abs_rel);
  // Counts: at most floor(1.1 x) frames, so that a baseline of none allows none.
  check("refused", now.refused, std::floor((1 + kSlack) * base.refused) / (1 + kSlack));
  check("failed", now.failed, std::floor((1 + kSlack) * base.failed) / (1 + kSlack));
  return worse;
}

// The comparison itself, on hand-made figures.
TEST(AccuracyGuardTest, WorseByMoreThanTenPerCentIsARegression) {
  SetFigures base;
  base.width_error = 0.02;
  base.abs_rel = 0.03;
  base.refused = 10;
  SetFigures now = base;
  EXPECT_TRUE(Regressions(now, base).empty());
  now.width_error = 0.0219;  // 9.5% worse: within the slack.
  now.refused = 11;          // 10% more.
  EXPECT_TRUE(Regressions(now, base).empty());
  now.width_error = 0.0221;
  now.abs_rel = 0.0331;
  now.refused = 12;
  now.failed = 1;  // Against a baseline of none.
  EXPECT_EQ(Regressions(now, base).size(), 4u);
  now = base;
  now.width_error = 0.001;  // Better is never a regression.
  EXPECT_TRUE(Regressions(now, base).empty());
}

// Both sets against the baseline; the demo also against its own bounds: every frame found, the
// width within 2% on average and 5% on each frame. (One test, so that the sets are rendered and
// recovered once.)
TEST(AccuracyGuardTest, TheGeneratedSetsKeepTheirAccuracy) {
  const auto& figures = Figures();
  if (const char* out = std::getenv("CORRIDOR_WRITE_ACCURACY_BASELINE")) {
    WriteBaseline(out, figures);
  }
  const SetFigures& demo = figures.at("demo");
  EXPECT_EQ(demo.frames, 12);
  EXPECT_EQ(demo.refused + demo.failed, 0);
  EXPECT_LE(demo.width_error, 0.02);
  EXPECT_LE(demo.max_width_error, 0.05);
  const auto baseline = ReadBaseline(BaselinePath());
  ASSERT_EQ(baseline.size(), figures.size()) << BaselinePath();
  for (const auto& [name, f] : figures) {
    const auto it = baseline.find(name);
    ASSERT_NE(it, baseline.end()) << name << " missing from " << BaselinePath();
    ASSERT_EQ(f.frames, it->second.frames) << name;
    for (const std::string& worse : Regressions(f, it->second)) {
      ADD_FAILURE() << name << ": " << worse << " (baseline " << BaselinePath() << ")";
    }
    std::printf(
        "%s: %d frames, %d refused, %d failed, width error %.3f%% (max %.2f%%), "
        "AbsRel < 5 m %.4f (baseline %.3f%%, %.4f)\n",
        name.c_str(), f.frames, f.refused, f.failed, 100 * f.width_error,
        100 * f.max_width_error, f.abs_rel, 100 * it->second.width_error,
        it->second.abs_rel);
  }
}

}  // namespace
}  // namespace corridor
