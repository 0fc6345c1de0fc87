#include "tools/geometry_csv.h"

#include <cstdio>

namespace corridor {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c == '\n' ? ' ' : c;
  }
  return quoted + "\"";
}

void GeometryCsv::Add(const std::string& frame, const RecoverDepthResult& result) {
  if (!result.has_geometry) {
    AddFailure(frame, result.status);
    return;
  }
  const CorridorGeometry& g = result.geometry;
  char numbers[256];
  std::snprintf(numbers, sizeof(numbers), "%.6f,%.6f,%.4f,%.4f,%s,%.6f", g.yaw, g.pitch, g.offset,
                g.width, g.HasCeiling() ? std::to_string(g.ceiling_height).c_str() : "",
                result.times.total);
  rows_.push_back(CsvField(frame) + "," +
                  CsvField(result.status.ok() ? "ok" : result.status.ToString()) + "," + numbers);
}

void GeometryCsv::AddFailure(const std::string& frame, const Status& status) {
  rows_.push_back(CsvField(frame) + "," + CsvField(status.ToString()) + ",,,,,,");
}

std::string GeometryCsv::Text() const {
  std::string text = "frame,status,yaw,pitch,offset,width,ceiling_height,seconds\n";
  for (const auto& row : rows_) text += row + "\n";
  return text;
}

}  // namespace corridor
