#pragma once

#include <string>
#include <vector>

#include "corridor_depth/status.h"
#include "tools/compare/solver_stats.h"

namespace corridor {

// solver_compare's outputs in `dir`: solver_compare.csv (every number), solver_compare.md (one
// table per case) and width_error_vs_noise.png (median width error against pixel noise, one
// line per solver, one panel per outlier fraction).
Status WriteCompareReport(const std::vector<SolverCaseStats>& rows, const std::string& dir);

// The Markdown tables (also printed by the tool).
std::string CompareMarkdown(const std::vector<SolverCaseStats>& rows);

}  // namespace corridor
