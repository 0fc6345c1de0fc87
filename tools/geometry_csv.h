#pragma once

#include <map>
#include <string>
#include <vector>

#include "io/csv_row.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// geometry.csv, one row per frame under the header kGeometryCsvHeader:
//   frame        the frame's name;
//   status       ok, refused (no corridor, implausible geometry, low confidence) or failed (a bad
//                input or a read error): core/status.h's StatusClass;
//   note         how an ok geometry came about (a held width, one junction, ...), or why the frame
//                was refused or failed, prefixed by its code ("no_corridor_found: ...");
//   confidence   the frame's confidence in [0, 1] (RecoverDepthResult::confidence);
//   yaw_rad, pitch_rad, offset_m, width_m, ceiling_height_m, end_distance_m: the geometry, with
//                the signs of docs/geometry.md;
//   roll_rad     the camera's roll the frame was recovered level from (0 when none was found;
//                the geometry is then the level camera's: RecoverDepthResult::roll);
//   fx_px, fy_px, cx_px, cy_px: the intrinsics the frame was recovered with;
//   time_s       the frame's computing time; stamp "<sec>.<nsec>" for a ROS bag message.
// An unknown value is empty.
extern const char kGeometryCsvHeader[];

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

// The status column and note of a frame's status: ("ok", "") or ("refused", "<code>: <message>").
std::pair<std::string, std::string> StatusColumns(const Status& status);

// The rows of an existing geometry.csv by frame name (the first field), without their newlines,
// in the current header's columns: a file with the previous header (frame,status,yaw,pitch,...)
// is migrated row by row. NotFound when the file does not exist; InvalidArgument naming the file
// and line when a row is malformed or the header is not geometry.csv's. `order` (may be null)
// receives the frame names in file order.
Status ReadGeometryCsvRows(const std::string& path, std::map<std::string, std::string>* rows,
                           std::vector<std::string>* order = nullptr);

}  // namespace corridor
