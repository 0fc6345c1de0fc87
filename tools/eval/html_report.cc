#include "tools/eval/html_report.h"

#include <cctype>
#include <cstdio>

#include "corridor_depth/evaluation.h"

namespace corridor {
namespace {

constexpr size_t kOpenAllBelow = 60;  // Frames: up to this many, every scene starts unfolded.

const char kStyle[] = R"(
body { font-family: sans-serif; margin: 24px; color: #222; max-width: 1600px; }
h1 { margin-bottom: 4px; }
table { border-collapse: collapse; margin: 8px 0 4px; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
th { background: #f0f0f0; }
td:first-child, th:first-child, td.text { text-align: left; }
tr.summary td { font-weight: bold; background: #fafaf0; }
p.note { font-size: 12px; color: #555; margin-top: 0; }
nav a { margin-right: 12px; }
.plots img { max-width: 100%; border: 1px solid #ddd; margin: 4px 0; }
figure { margin: 10px 0 18px; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 13px; }
figure.failed figcaption { color: #b00; font-weight: bold; }
details { margin: 6px 0; }
summary { font-size: 16px; cursor: pointer; }
)";

// Numbers (and "-", "3 / 4", "1.2 / 3.4") are right-aligned; text is left-aligned.
bool IsNumeric(const std::string& cell) {
  for (char c : cell) {
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != ' ' &&
        c != '/' && c != 'e' && c != '+') {
      return false;
    }
  }
  return true;
}

std::string HtmlTable(const TextTable& table) {
  std::string out =
      "<h2 id=\"" + HtmlEscape(table.id) + "\">" + HtmlEscape(table.title) + "</h2>\n<table>\n<tr>";
  for (const auto& h : table.header) out += "<th>" + HtmlEscape(h) + "</th>";
  out += "</tr>\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    const bool summary = r < table.summary.size() && table.summary[r];
    out += summary ? "<tr class=\"summary\">" : "<tr>";
    for (const auto& cell : table.rows[r]) {
      out += (IsNumeric(cell) ? "<td>" : "<td class=\"text\">") + HtmlEscape(cell) + "</td>";
    }
    out += "</tr>\n";
  }
  out += "</table>\n";
  if (!table.note.empty()) out += "<p class=\"note\">" + HtmlEscape(table.note) + "</p>\n";
  return out;
}

std::string FrameCaption(const FrameRecord& f, const std::vector<double>& caps) {
  std::string text = f.scene + " / " + f.frame + " — ";
  if (!f.status.ok()) return text + "FAILED: " + f.status.ToString();
  char part[96];
  std::snprintf(part, sizeof(part), "width %.2f m", f.estimate.width);
  text += part;
  if (f.has_truth) {
    std::snprintf(part, sizeof(part), " (true %.2f m)", f.truth.width);
    text += part;
  }
  for (size_t c = 0; c < caps.size() && c < f.metrics.size(); ++c) {
    if (!f.has_depth_truth) break;
    text += "; AbsRel " + CapLabel(caps[c]) + ": " + FormatNumber(f.metrics[c].abs_rel, 4);
  }
  std::snprintf(part, sizeof(part), "; %.1f ms", f.times.total * 1e3);
  return text + part;
}

std::string FrameSection(const EvalReport& r) {
  std::string out =
      "<h2 id=\"frames\">Frames</h2>\n<p class=\"note\">Each picture: input with "
      "the junction lines | predicted depth | ground truth (one depth scale) | "
      "absolute error (its own scale). Click for full size.</p>\n";
  for (size_t s = 0; s < r.scenes.size(); ++s) {
    const GroupSummary& scene = r.scenes[s];
    const bool open = s == 0 || r.frames.size() <= kOpenAllBelow;
    out += std::string("<details") + (open ? " open" : "") + "><summary>" + HtmlEscape(scene.name) +
           " (" + std::to_string(scene.num_frames) + " frames, " +
           std::to_string(scene.num_failed) + " failed)</summary>\n";
    for (const FrameRecord& f : r.frames) {
      if (f.scene != scene.name) continue;
      const std::string src = UrlPath(VisRelativePath(f.scene, f.frame));
      out += std::string("<figure") + (f.status.ok() ? "" : " class=\"failed\"") + "><a href=\"" +
             src + "\"><img loading=\"lazy\" src=\"" + src + "\" alt=\"" +
             HtmlEscape(f.scene + "/" + f.frame) + "\"></a><figcaption>" +
             HtmlEscape(FrameCaption(f, r.caps)) + "</figcaption></figure>\n";
    }
    out += "</details>\n";
  }
  return out;
}

}  // namespace

std::string HtmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string UrlPath(const std::string& path) {
  std::string out;
  for (char c : path) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      out += c;
    } else {
      char escaped[4];
      std::snprintf(escaped, sizeof(escaped), "%%%02X", u);
      out += escaped;
    }
  }
  return out;
}

std::string ReportHtml(const std::vector<EvalReport>& configs, const ReportContext& context,
                       bool with_vis) {
  std::string out =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>corridor_eval report</title>\n<style>" +
      std::string(kStyle) + "</style>\n</head>\n<body>\n<h1>corridor_eval report</h1>\n";
  if (configs.empty()) return out + "<p>Nothing was evaluated.</p>\n</body>\n</html>\n";
  const EvalReport& r = configs.front();
  out += "<p>Dataset <code>" + HtmlEscape(context.dataset) + "</code>; solver <code>" +
         HtmlEscape(r.solver) + "</code>, rasterizer <code>" + HtmlEscape(r.rasterizer) +
         "</code>; " + std::to_string(r.all.num_frames) + " frames in " +
         std::to_string(r.scenes.size()) + " scenes, " + std::to_string(r.all.num_failed) +
         " failed. Numbers also in <a href=\"report.json\">report.json</a>, "
         "<a href=\"report.csv\">report.csv</a>, <a href=\"report.md\">report.md</a>.</p>\n";
  const std::vector<TextTable> tables = ReportTables(configs);
  out += "<nav>";
  for (const auto& t : tables)
    out += "<a href=\"#" + HtmlEscape(t.id) + "\">" + HtmlEscape(t.id) + "</a>";
  out += "<a href=\"#plots\">plots</a>";
  if (with_vis) out += "<a href=\"#frames\">frames</a>";
  out += "</nav>\n";
  for (const auto& t : tables) out += HtmlTable(t);
  out += "<h2 id=\"plots\">Plots</h2>\n<div class=\"plots\">\n";
  for (const auto& plot : context.plot_files) {
    out += "<div><img src=\"" + UrlPath(plot) + "\" alt=\"" + HtmlEscape(plot) + "\"></div>\n";
  }
  out += "</div>\n";
  if (with_vis) out += FrameSection(r);
  return out + "</body>\n</html>\n";
}

}  // namespace corridor
