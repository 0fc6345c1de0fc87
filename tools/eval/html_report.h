#pragma once

#include <string>
#include <vector>

#include "corridor_depth/evaluation.h"
#include "tools/eval/report_writers.h"

namespace corridor {

// index.html: a static page (no scripts, no external assets) with the tables, the plots and,
// when `with_vis`, every frame's picture (vis/<scene>/<frame>.png), all by relative links.
std::string ReportHtml(const std::vector<EvalReport>& configs, const ReportContext& context,
                       bool with_vis);

// Text with &, <, >, " and ' escaped for HTML.
std::string HtmlEscape(const std::string& text);

// A relative path percent-encoded for an href/src (slashes kept).
std::string UrlPath(const std::string& path);

}  // namespace corridor
