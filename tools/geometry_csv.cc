#include "tools/geometry_csv.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace corridor {
namespace {

constexpr char kHeader[] = "frame,status,yaw,pitch,offset,width,ceiling_height,end_distance,seconds,stamp";

// The first field of a CSV row, unquoted as CsvField quotes it; false when it is malformed.
bool FirstField(const std::string& row, std::string* field) {
  field->clear();
  if (row.empty() || row[0] != '"') {
    *field = row.substr(0, row.find(','));
    return !field->empty();
  }
  for (size_t i = 1; i < row.size(); ++i) {
    if (row[i] != '"') {
      *field += row[i];
    } else if (i + 1 < row.size() && row[i + 1] == '"') {
      *field += '"';
      ++i;
    } else {
      return !field->empty() && (i + 1 == row.size() || row[i + 1] == ',');
    }
  }
  return false;  // No closing quote.
}

}  // namespace

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c == '\n' ? ' ' : c;
  }
  return quoted + "\"";
}

void GeometryCsv::Add(const std::string& frame, const RecoverDepthResult& result,
                      const std::string& stamp) {
  if (!result.has_geometry) {
    AddFailure(frame, result.status, stamp);
    return;
  }
  const CorridorGeometry& g = result.geometry;
  char numbers[256];
  std::snprintf(numbers, sizeof(numbers), "%.6f,%.6f,%.4f,%.4f,%s,%s,%.6f", g.yaw, g.pitch,
                g.offset, g.width, g.HasCeiling() ? std::to_string(g.ceiling_height).c_str() : "",
                g.HasEndWall() ? std::to_string(g.end_distance).c_str() : "", result.times.total);
  rows_.push_back(CsvField(frame) + "," +
                  CsvField(!result.status.ok()        ? result.status.ToString()
                           : result.fallback.empty() ? std::string("ok")
                                                     : "ok: " + result.fallback) +
                  "," + numbers +
                  "," + CsvField(stamp));
}

void GeometryCsv::AddFailure(const std::string& frame, const Status& status,
                            const std::string& stamp) {
  rows_.push_back(CsvField(frame) + "," + CsvField(status.ToString()) + ",,,,,,," + "," +
                  CsvField(stamp));
}

std::string GeometryCsv::Text() const {
  std::string text = std::string(kHeader) + "\n";
  for (const auto& row : rows_) text += row + "\n";
  return text;
}

Status ReadGeometryCsvRows(const std::string& path, std::map<std::string, std::string>* rows) {
  rows->clear();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return Status::NotFound(path + ": no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::IoError(path + ": cannot open for reading");
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1) {
      if (line != kHeader) {
        return Status::InvalidArgument(path + ": line 1 is not the geometry.csv header '" +
                                       std::string(kHeader) + "'");
      }
      continue;
    }
    if (line.empty()) continue;
    std::string frame;
    if (!FirstField(line, &frame)) {
      return Status::InvalidArgument(path + ": line " + std::to_string(number) +
                                     " has no frame name");
    }
    (*rows)[frame] = line;
  }
  if (in.bad()) return Status::IoError(path + ": read failed");
  return Status::Ok();
}

}  // namespace corridor
