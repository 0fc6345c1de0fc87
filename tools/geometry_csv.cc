#include "tools/geometry_csv.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace corridor {

const char kGeometryCsvHeader[] =
    "frame,status,note,confidence,yaw_rad,pitch_rad,roll_rad,offset_m,width_m,ceiling_height_m,"
    "end_distance_m,fx_px,fy_px,cx_px,cy_px,time_s,stamp";

namespace {

// The headers geometry.csv had before: before units and the status/note split, and before the
// roll column. Their rows are migrated.
constexpr char kOldestHeader[] =
    "frame,status,yaw,pitch,offset,width,ceiling_height,end_distance,seconds,stamp";
constexpr char kHeaderWithoutRoll[] =
    "frame,status,note,confidence,yaw_rad,pitch_rad,offset_m,width_m,ceiling_height_m,"
    "end_distance_m,fx_px,fy_px,cx_px,cy_px,time_s,stamp";
constexpr size_t kFields = 17;

std::string Number(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

std::string JoinRow(const std::vector<std::string>& fields) {
  std::string row;
  for (size_t i = 0; i < fields.size(); ++i) row += (i ? "," : "") + CsvField(fields[i]);
  return row;
}

// A previous-header status ("ok", "ok: <how>", "<code words>: <message>") as status and note.
std::pair<std::string, std::string> MigrateStatus(const std::string& old) {
  if (old == "ok") return {"ok", ""};
  if (old.rfind("ok: ", 0) == 0) return {"ok", old.substr(4)};
  for (const StatusCode code :
       {StatusCode::kInvalidArgument, StatusCode::kNotFound, StatusCode::kIoError,
        StatusCode::kNoCorridorFound, StatusCode::kImplausibleGeometry, StatusCode::kInternal}) {
    const std::string words = std::string(StatusCodeToString(code)) + ": ";
    if (old.rfind(words, 0) == 0) {
      return {StatusClass(code), std::string(StatusCodeName(code)) + ": " + old.substr(words.size())};
    }
  }
  return {"failed", old};
}

}  // namespace

std::pair<std::string, std::string> StatusColumns(const Status& status) {
  if (status.ok()) return {"ok", ""};
  return {StatusClass(status.code()),
          std::string(StatusCodeName(status.code())) + ": " + status.message()};
}

void GeometryCsv::Add(const std::string& frame, const RecoverDepthResult& result,
                      const std::string& stamp) {
  auto [status, note] = StatusColumns(result.status);
  if (result.status.ok()) note = result.fallback;
  std::vector<std::string> fields(kFields);
  fields[0] = frame, fields[1] = status, fields[2] = note, fields[16] = stamp;
  if (result.has_geometry) {
    const CorridorGeometry& g = result.geometry;
    fields[4] = Number(g.yaw, "%.6f"), fields[5] = Number(g.pitch, "%.6f");
    fields[6] = Number(result.roll, "%.6f");
    fields[7] = Number(g.offset, "%.4f"), fields[8] = Number(g.width, "%.4f");
    if (g.HasCeiling()) fields[9] = Number(g.ceiling_height, "%.4f");
    if (g.HasEndWall()) fields[10] = Number(g.end_distance, "%.4f");
  }
  if (result.camera.fx > 0) {  // A frame that was read: its confidence, intrinsics and time.
    fields[3] = Number(result.confidence, "%.3f");
    fields[11] = Number(result.camera.fx, "%.3f"), fields[12] = Number(result.camera.fy, "%.3f");
    fields[13] = Number(result.camera.cx, "%.3f"), fields[14] = Number(result.camera.cy, "%.3f");
    fields[15] = Number(result.times.total, "%.6f");
  }
  rows_.push_back(JoinRow(fields));
}

void GeometryCsv::AddFailure(const std::string& frame, const Status& status,
                             const std::string& stamp) {
  const auto [code, note] = StatusColumns(status);
  std::vector<std::string> fields(kFields);
  fields[0] = frame, fields[1] = code, fields[2] = note, fields[16] = stamp;
  rows_.push_back(JoinRow(fields));
}

std::string GeometryCsv::Text() const {
  std::string text = std::string(kGeometryCsvHeader) + "\n";
  for (const auto& row : rows_) text += row + "\n";
  return text;
}

Status ReadGeometryCsvRows(const std::string& path, std::map<std::string, std::string>* rows,
                           std::vector<std::string>* order) {
  rows->clear();
  if (order != nullptr) order->clear();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return Status::NotFound(path + ": no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::IoError(path + ": cannot open for reading");
  std::string line;
  int number = 0;
  bool oldest = false, without_roll = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1) {
      oldest = line == kOldestHeader;
      without_roll = line == kHeaderWithoutRoll;
      if (line != kGeometryCsvHeader && !oldest && !without_roll) {
        return Status::InvalidArgument(path + ": line 1 is not the geometry.csv header '" +
                                       std::string(kGeometryCsvHeader) +
                                       "' (nor an earlier one); the file is left as it is");
      }
      continue;
    }
    if (line.empty()) continue;
    std::vector<std::string> fields;
    const size_t expected = oldest ? 10 : without_roll ? kFields - 1
                                                       : kFields;
    if (!SplitCsvRow(line, &fields) || fields.size() != expected || fields[0].empty()) {
      return Status::InvalidArgument(path + ": line " + std::to_string(number) +
                                     " is not a geometry.csv row of " + std::to_string(expected) +
                                     " fields with a frame name; the file is left as it is");
    }
    if (oldest) {  // frame,status,yaw,pitch,offset,width,ceiling_height,end_distance,seconds,stamp
      const auto [status, note] = MigrateStatus(fields[1]);
      line = JoinRow({fields[0], status, note, "", fields[2], fields[3], "", fields[4], fields[5],
                      fields[6], fields[7], "", "", "", "", fields[8], fields[9]});
    } else if (without_roll) {  // The roll column, unknown, after pitch_rad.
      fields.insert(fields.begin() + 6, "");
      line = JoinRow(fields);
    }
    if (order != nullptr && rows->count(fields[0]) == 0) order->push_back(fields[0]);
    (*rows)[fields[0]] = line;
  }
  if (in.bad()) return Status::IoError(path + ": read failed");
  return Status::Ok();
}

}  // namespace corridor
