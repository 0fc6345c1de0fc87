#include "corridor_depth/evaluation.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

namespace corridor {
namespace {

// Mean of the non-NaN values; NaN when there is none.
double MeanOf(const std::vector<double>& values) {
  double sum = 0;
  int count = 0;
  for (double v : values) {
    if (std::isnan(v)) continue;
    sum += v;
    ++count;
  }
  return count > 0 ? sum / count : kUnknown;
}

TimeSummary Summarize(const std::vector<double>& seconds) {
  TimeSummary t;
  t.median = Percentile(seconds, 50);
  t.p90 = Percentile(seconds, 90);
  return t;
}

std::string Trim(const std::string& text) {
  size_t begin = 0, end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return text.substr(begin, end - begin);
}

// Everything but the width's scene-level fields, over the frames `members` (indices).
GroupSummary Summarize(const std::string& name, const std::vector<FrameRecord>& frames,
                       const std::vector<size_t>& members, size_t num_caps) {
  GroupSummary g;
  g.name = name;
  std::vector<std::vector<DepthMetrics>> per_cap(num_caps);
  std::vector<double> est_width, true_width, frame_width_error, yaw, pitch, offset;
  std::vector<double> t_perception, t_solve, t_rasterize, t_total, ceiling_error;
  for (size_t i : members) {
    const FrameRecord& f = frames[i];
    ++g.num_frames;
    if (!f.status.ok()) ++g.num_failed;
    if (f.has_depth_truth) {
      ++g.num_depth_truth;
      for (size_t c = 0; c < num_caps && c < f.metrics.size(); ++c) {
        per_cap[c].push_back(f.metrics[c]);
      }
    }
    if (f.has_estimate) est_width.push_back(f.estimate.width);
    if (f.has_truth) true_width.push_back(f.truth.width);
    if (f.has_estimate && f.has_truth) {
      frame_width_error.push_back(RelativeError(f.estimate.width, f.truth.width));
      if (frame_width_error.back() > kGrossWidthError) ++g.width.num_gross;
      yaw.push_back(std::abs(f.estimate.yaw - f.truth.yaw));
      pitch.push_back(std::abs(f.estimate.pitch - f.truth.pitch));
      offset.push_back(std::abs(f.estimate.offset - f.truth.offset));
    }
    if (f.has_truth && f.ceiling_visible) {
      ++g.ceiling.num_visible;
      if (f.ceiling_estimated) {
        // Visible implies a true ceiling above the camera: the error is a number.
        const double error = RelativeError(f.estimate.ceiling_height, f.truth.ceiling_height);
        ceiling_error.push_back(error);
        if (error <= kCeilingTolerance) ++g.ceiling.num_within;
      }
    }
    if (f.ran) {
      t_perception.push_back(f.times.perception);
      t_solve.push_back(f.times.solve);
      t_rasterize.push_back(f.times.rasterize);
      t_total.push_back(f.times.total);
    }
  }
  for (const auto& metrics : per_cap) g.depth.push_back(AverageDepthMetrics(metrics));
  g.width.estimated = MeanOf(est_width);
  g.width.truth = MeanOf(true_width);
  g.width.rel_error = RelativeError(g.width.estimated, g.width.truth);
  g.width.mean_frame_rel_error = MeanOf(frame_width_error);
  g.width.num_estimated = static_cast<int>(est_width.size());
  g.width.num_truth = static_cast<int>(true_width.size());
  g.pose.yaw = MeanOf(yaw);
  g.pose.pitch = MeanOf(pitch);
  g.pose.offset = MeanOf(offset);
  g.pose.num_frames = static_cast<int>(yaw.size());
  g.ceiling.num_found = static_cast<int>(ceiling_error.size());
  g.ceiling.mean_rel_error = MeanOf(ceiling_error);
  if (!ceiling_error.empty()) {
    g.ceiling.max_rel_error = *std::max_element(ceiling_error.begin(), ceiling_error.end());
  }
  g.timing.perception = Summarize(t_perception);
  g.timing.solve = Summarize(t_solve);
  g.timing.rasterize = Summarize(t_rasterize);
  g.timing.total = Summarize(t_total);
  g.timing.num_frames = static_cast<int>(t_total.size());
  return g;
}

// A group of scenes: widths of different corridors are not averaged; its relative width error
// is the mean of its scenes' (as the paper's "mean relative error").
GroupSummary SummarizeGroup(const std::string& name, const std::vector<FrameRecord>& frames,
                            const std::vector<size_t>& members, size_t num_caps,
                            const std::vector<const GroupSummary*>& scenes) {
  GroupSummary g = Summarize(name, frames, members, num_caps);
  std::vector<double> scene_errors;
  for (const GroupSummary* s : scenes) scene_errors.push_back(s->width.rel_error);
  g.width.estimated = kUnknown;
  g.width.truth = kUnknown;
  g.width.rel_error = MeanOf(scene_errors);
  return g;
}

}  // namespace

EvalReport BuildReport(const std::vector<FrameRecord>& frames, const std::vector<double>& caps,
                       const std::string& solver, const std::string& rasterizer) {
  EvalReport report;
  report.solver = solver;
  report.rasterizer = rasterizer;
  report.caps = caps;
  report.frames = frames;

  std::vector<std::string> scene_order;
  std::map<std::string, std::vector<size_t>> scene_members;
  std::vector<size_t> everything;
  for (size_t i = 0; i < frames.size(); ++i) {
    if (scene_members.count(frames[i].scene) == 0) scene_order.push_back(frames[i].scene);
    scene_members[frames[i].scene].push_back(i);
    everything.push_back(i);
    if (!frames[i].status.ok()) {
      report.failures.push_back({frames[i].scene, frames[i].frame, frames[i].status.ToString()});
    }
  }
  for (const auto& name : scene_order) {
    report.scenes.push_back(Summarize(name, frames, scene_members[name], caps.size()));
  }

  std::vector<const GroupSummary*> all_scenes;
  for (const auto& s : report.scenes) all_scenes.push_back(&s);
  report.all = SummarizeGroup("all", frames, everything, caps.size(), all_scenes);
  for (const std::string group : {"easy", "hard"}) {
    std::vector<size_t> members;
    std::vector<const GroupSummary*> scenes;
    for (const auto& s : report.scenes) {
      if (SceneDifficulty(s.name) != group) continue;
      scenes.push_back(&s);
      const auto& m = scene_members[s.name];
      members.insert(members.end(), m.begin(), m.end());
    }
    std::sort(members.begin(), members.end());
    if (!scenes.empty()) {
      report.groups.push_back(SummarizeGroup(group, frames, members, caps.size(), scenes));
    }
  }

  double max_cap = 0;
  for (double cap : caps) max_cap = std::max(max_cap, cap);
  const int num_bins = static_cast<int>(std::ceil(max_cap));
  std::vector<DepthBin> bins(num_bins);
  for (const auto& f : frames) {
    for (size_t k = 0; k < f.depth_bins.size() && k < bins.size(); ++k) {
      bins[k].abs_rel_sum += f.depth_bins[k].abs_rel_sum;
      bins[k].pixels += f.depth_bins[k].pixels;
    }
  }
  for (int k = 0; k < num_bins; ++k) {
    DepthBinSummary bin;
    bin.start = k;
    bin.end = std::min<double>(k + 1, max_cap);
    bin.pixels = bins[k].pixels;
    if (bin.pixels > 0) bin.abs_rel = bins[k].abs_rel_sum / static_cast<double>(bin.pixels);
    report.depth_bins.push_back(bin);
  }
  return report;
}

std::string SceneDifficulty(const std::string& scene) {
  for (size_t i = 0; i + 1 < scene.size(); ++i) {
    if (i > 0 && scene[i - 1] != '_') continue;
    if (!std::isdigit(static_cast<unsigned char>(scene[i + 1]))) continue;
    if (scene[i] == 'E') return "easy";
    if (scene[i] == 'H') return "hard";
  }
  return "";
}

std::string CapKey(double cap) {
  char text[64];
  if (cap == std::floor(cap) && std::abs(cap) < 1e9) {
    std::snprintf(text, sizeof(text), "lt%lld", static_cast<long long>(cap));
  } else {
    std::snprintf(text, sizeof(text), "lt%g", cap);
  }
  std::string key = text;
  std::replace(key.begin(), key.end(), '.', 'p');
  return key;
}

Status ParseCaps(const std::string& text, std::vector<double>* caps) {
  caps->clear();
  if (Trim(text).empty()) return Status::InvalidArgument("--caps is empty (expected e.g. 5,40)");
  std::set<std::string> keys;
  size_t begin = 0;
  while (true) {
    const size_t comma = text.find(',', begin);
    const std::string item = Trim(text.substr(begin, comma - begin));
    if (item.empty()) {
      return Status::InvalidArgument("--caps=" + text + " has an empty entry (expected e.g. 5,40)");
    }
    char* end = nullptr;
    errno = 0;
    const double cap = std::strtod(item.c_str(), &end);
    if (end != item.c_str() + item.size() || errno == ERANGE) {
      return Status::InvalidArgument("--caps: '" + item + "' is not a number (expected e.g. 5,40)");
    }
    if (!std::isfinite(cap) || !(cap > 0)) {
      return Status::InvalidArgument("--caps: " + item + " must be a positive depth in metres");
    }
    if (cap > 1000) {
      return Status::InvalidArgument("--caps: " + item + " m is beyond any corridor (max 1000)");
    }
    if (!keys.insert(CapKey(cap)).second) {
      return Status::InvalidArgument("--caps: " + item + " is given twice");
    }
    caps->push_back(cap);
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return Status::Ok();
}

double Percentile(std::vector<double> values, double p) {
  if (values.empty()) return kUnknown;
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(values.size() - 1);
  const size_t lower = static_cast<size_t>(std::floor(pos));
  const size_t upper = std::min(lower + 1, values.size() - 1);
  const double t = pos - static_cast<double>(lower);
  return values[lower] + t * (values[upper] - values[lower]);
}

}  // namespace corridor
