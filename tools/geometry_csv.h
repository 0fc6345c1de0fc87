#pragma once

#include <map>
#include <string>
#include <vector>

#include "pipeline/recover_depth.h"

namespace corridor {

// geometry.csv: a header row, then `frame,status,yaw,pitch,offset,width,ceiling_height,
// end_distance,seconds,stamp` per frame; radians and metres with the signs of docs/geometry.md;
// status "ok", "ok: <how>" when one junction and a known width gave the geometry, or the error;
// stamp "<sec>.<nsec>" for a ROS bag message; an unknown value is empty.
class GeometryCsv {
 public:
  void Add(const std::string& frame, const RecoverDepthResult& result,
           const std::string& stamp = "");
  void AddFailure(const std::string& frame, const Status& status, const std::string& stamp = "");
  // A row as an earlier run wrote it (without the newline), e.g. from ReadGeometryCsvRows.
  void AddRow(const std::string& row) { rows_.push_back(row); }
  std::string Text() const;
  const std::vector<std::string>& rows() const { return rows_; }  // Without newlines.
  int size() const { return static_cast<int>(rows_.size()); }

 private:
  std::vector<std::string> rows_;
};

// Quotes a CSV field when it holds a comma, quote or newline.
std::string CsvField(const std::string& text);

// The rows of an existing geometry.csv by frame name (the first field, unquoted), without their
// newlines, for resuming a run. NotFound when the file does not exist; InvalidArgument naming the
// file and line when a row has no frame name or the header is not geometry.csv's.
Status ReadGeometryCsvRows(const std::string& path, std::map<std::string, std::string>* rows);

}  // namespace corridor
