// report.json, written by hand (report_writers.h).

#include <cmath>
#include <cstdio>
#include <utility>

#include "tools/eval/report_writers.h"

namespace corridor {
namespace {

// A JSON object under construction: keys with raw JSON values, printed indented.
class JsonObject {
 public:
  JsonObject& Add(const std::string& key, std::string raw_value) {
    fields_.emplace_back(key, std::move(raw_value));
    return *this;
  }
  JsonObject& Number(const std::string& key, double value) { return Add(key, JsonNumber(value)); }
  JsonObject& Int(const std::string& key, int64_t value) { return Add(key, std::to_string(value)); }
  JsonObject& String(const std::string& key, const std::string& value) {
    return Add(key, JsonString(value));
  }
  JsonObject& Bool(const std::string& key, bool value) { return Add(key, value ? "true" : "false"); }
  // Nested values are indented by re-indenting their lines.
  std::string Text() const {
    if (fields_.empty()) return "{}";
    std::string out = "{\n";
    for (size_t i = 0; i < fields_.size(); ++i) {
      out += "  " + JsonString(fields_[i].first) + ": " + Indent(fields_[i].second);
      out += i + 1 < fields_.size() ? ",\n" : "\n";
    }
    return out + "}";
  }

 private:
  static std::string Indent(const std::string& text) {
    std::string out;
    for (char c : text) {
      out += c;
      if (c == '\n') out += "  ";
    }
    return out;
  }
  std::vector<std::pair<std::string, std::string>> fields_;
};

std::string Array(const std::vector<std::string>& raw_values) {
  if (raw_values.empty()) return "[]";
  std::string out = "[\n";
  for (size_t i = 0; i < raw_values.size(); ++i) {
    std::string item;
    for (char c : raw_values[i]) {
      item += c;
      if (c == '\n') item += "  ";
    }
    out += "  " + item + (i + 1 < raw_values.size() ? ",\n" : "\n");
  }
  return out + "]";
}

std::string Metrics(const DepthMetrics& m) {
  JsonObject o;
  o.Number("abs_rel", m.abs_rel).Number("log10", m.log10).Number("rmse", m.rmse);
  o.Number("rmse_log10", m.rmse_log10).Number("rmse_log", m.rmse_log).Number("sq_rel", m.sq_rel);
  o.Number("delta1", m.delta1).Number("delta2", m.delta2).Number("delta3", m.delta3);
  o.Number("coverage", m.coverage).Int("num_images", m.num_images).Int("num_gt", m.num_gt);
  o.Int("num_evaluated", m.num_evaluated);
  return o.Text();
}

std::string Geometry(const CorridorGeometry& g) {
  JsonObject o;
  o.Number("yaw", g.yaw).Number("pitch", g.pitch).Number("offset", g.offset);
  o.Number("width", g.width).Number("camera_height", g.camera_height);
  o.Number("ceiling_height", g.ceiling_height > 0 ? g.ceiling_height : kUnknown);
  return o.Text();
}

std::string Time(const TimeSummary& t) {
  return JsonObject().Number("median_s", t.median).Number("p90_s", t.p90).Text();
}

std::string Group(const GroupSummary& g, const std::vector<double>& caps, bool is_scene) {
  JsonObject o;
  o.Int("num_frames", g.num_frames).Int("num_failed", g.num_failed);
  o.Int("num_depth_truth", g.num_depth_truth);
  if (is_scene) o.String("difficulty", SceneDifficulty(g.name));
  JsonObject width;
  width.Number("estimated", g.width.estimated).Number("truth", g.width.truth);
  width.Number("rel_error", g.width.rel_error);
  width.Number("mean_frame_rel_error", g.width.mean_frame_rel_error);
  width.Int("num_estimated", g.width.num_estimated).Int("num_truth", g.width.num_truth);
  width.Int("num_gross", g.width.num_gross);
  o.Add("width", width.Text());
  JsonObject pose;
  pose.Number("yaw_abs_error_rad", g.pose.yaw).Number("pitch_abs_error_rad", g.pose.pitch);
  pose.Number("offset_abs_error_m", g.pose.offset).Int("num_frames", g.pose.num_frames);
  o.Add("pose", pose.Text());
  JsonObject ceiling;
  ceiling.Int("num_visible", g.ceiling.num_visible).Int("num_found", g.ceiling.num_found);
  ceiling.Int("num_within_tolerance", g.ceiling.num_within);
  ceiling.Number("tolerance", kCeilingTolerance);
  ceiling.Number("mean_rel_error", g.ceiling.mean_rel_error);
  ceiling.Number("max_rel_error", g.ceiling.max_rel_error);
  o.Add("ceiling", ceiling.Text());
  JsonObject timing;
  timing.Add("perception", Time(g.timing.perception)).Add("solve", Time(g.timing.solve));
  timing.Add("rasterize", Time(g.timing.rasterize)).Add("total", Time(g.timing.total));
  timing.Int("num_frames", g.timing.num_frames);
  o.Add("timing", timing.Text());
  for (size_t c = 0; c < caps.size() && c < g.depth.size(); ++c) {
    o.Add(CapKey(caps[c]), Metrics(g.depth[c]));
  }
  return o.Text();
}

std::string Frame(const FrameRecord& f, const std::vector<double>& caps) {
  JsonObject o;
  o.String("scene", f.scene).String("frame", f.frame);
  o.String("status", StatusClass(f.status.code())).String("reason", f.status.ToString());
  o.Add("estimate", f.has_estimate ? Geometry(f.estimate) : "null");
  o.Add("truth", f.has_truth ? Geometry(f.truth) : "null");
  o.Number("width_rel_error", f.has_estimate && f.has_truth
                                  ? RelativeError(f.estimate.width, f.truth.width)
                                  : kUnknown);
  o.Bool("ceiling_visible", f.ceiling_visible).Bool("ceiling_estimated", f.ceiling_estimated);
  o.Bool("junctions_tracked", f.junctions_tracked);
  for (size_t c = 0; c < caps.size() && c < f.metrics.size(); ++c) {
    o.Add(CapKey(caps[c]), Metrics(f.metrics[c]));
  }
  JsonObject times;
  times.Number("perception_s", f.ran ? f.times.perception : kUnknown);
  times.Number("solve_s", f.ran ? f.times.solve : kUnknown);
  times.Number("rasterize_s", f.ran ? f.times.rasterize : kUnknown);
  times.Number("total_s", f.ran ? f.times.total : kUnknown);
  o.Add("times", times.Text());
  return o.Text();
}

// Every field of one configuration, added to `o`.
void AddConfig(const EvalReport& r, JsonObject* o) {
  o->String("solver", r.solver).String("rasterizer", r.rasterizer);
  std::vector<std::string> caps, keys;
  for (double cap : r.caps) {
    caps.push_back(JsonNumber(cap));
    keys.push_back(JsonString(CapKey(cap)));
  }
  o->Add("caps", Array(caps)).Add("cap_keys", Array(keys));
  o->Int("num_frames", r.all.num_frames).Int("num_failed", r.all.num_failed);
  JsonObject scenes;
  for (const auto& s : r.scenes) scenes.Add(s.name, Group(s, r.caps, true));
  o->Add("scenes", scenes.Text());
  o->Add("all", Group(r.all, r.caps, false));
  for (const auto& g : r.groups) o->Add(g.name, Group(g, r.caps, false));
  std::vector<std::string> bins;
  for (const auto& b : r.depth_bins) {
    bins.push_back(JsonObject()
                       .Number("start_m", b.start)
                       .Number("end_m", b.end)
                       .Number("abs_rel", b.abs_rel)
                       .Int("pixels", b.pixels)
                       .Text());
  }
  o->Add("abs_rel_by_depth", Array(bins));
  std::vector<std::string> failures;
  for (const auto& f : r.failures) {
    failures.push_back(JsonObject()
                           .String("scene", f.scene)
                           .String("frame", f.frame)
                           .String("reason", f.reason)
                           .Text());
  }
  o->Add("failures", Array(failures));
  std::vector<std::string> frames;
  for (const auto& f : r.frames) frames.push_back(Frame(f, r.caps));
  o->Add("frames", Array(frames));
}

}  // namespace

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      default:
        if (u < 0x20 || u == 0x7f) {
          char escaped[8];
          std::snprintf(escaped, sizeof(escaped), "\\u%04x", u);
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string JsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char text[40];
  std::snprintf(text, sizeof(text), "%.15g", value);
  return text;
}

std::string ReportJson(const std::vector<EvalReport>& configs, const ReportContext& context) {
  JsonObject root;
  root.String("tool", "corridor_eval").String("dataset", context.dataset);
  root.Add("sequence", context.sequence ? "true" : "false");
  if (configs.empty()) return root.Text() + "\n";
  AddConfig(configs.front(), &root);
  std::vector<std::string> plots;
  for (const auto& p : context.plot_files) plots.push_back(JsonString(p));
  root.Add("plots", Array(plots));
  if (configs.size() > 1) {
    std::vector<std::string> names;
    JsonObject all_configs;
    for (const auto& r : configs) {
      names.push_back(JsonString(r.ConfigName()));
      JsonObject one;
      AddConfig(r, &one);
      all_configs.Add(r.ConfigName(), one.Text());
    }
    root.Add("config_order", Array(names));
    root.Add("configs", all_configs.Text());
  }
  return root.Text() + "\n";
}

}  // namespace corridor
