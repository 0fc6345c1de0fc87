#pragma once

#include <string>
#include <vector>

#include "evaluation/report_builder.h"

namespace corridor {

// A table as text cells, rendered as Markdown or HTML.
struct TextTable {
  std::string id;                              // Anchor name, e.g. "table1".
  std::string title;                           // Caption, e.g. "Table 1: ...".
  std::vector<std::string> header;             // Column titles.
  std::vector<std::vector<std::string>> rows;  // Cells, row by row.
  std::vector<bool> summary;                   // Per row: a group row (all/easy/hard), in bold.
  std::string note;                            // A footnote ("" for none).
};

// The report's tables for the first configuration, in the paper's layout: Table 1 (width),
// one depth table per cap (Tables 2, 3: AbsRel, Log10, RMSE, RMSElog first), pose errors,
// timing, and, with more than one configuration, a Table 4-style comparison on the "all" row;
// failures last when there are any.
std::vector<TextTable> ReportTables(const std::vector<EvalReport>& configs);

// A number with `decimals` decimals, "-" for NaN.
std::string FormatNumber(double value, int decimals);

// "depth < 5 m" for a cap.
std::string CapLabel(double cap);

}  // namespace corridor
