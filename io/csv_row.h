#pragma once

#include <string>
#include <vector>

namespace corridor {

// Quotes a CSV field when it holds a comma, quote or newline (a newline becomes a space).
std::string CsvField(const std::string& text);

// The fields of one CSV row (RFC 4180 quoting), unquoted; false when a quote is not closed.
bool SplitCsvRow(const std::string& row, std::vector<std::string>* fields);

}  // namespace corridor
