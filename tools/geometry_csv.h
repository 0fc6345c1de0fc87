#pragma once

#include <string>
#include <vector>

#include "pipeline/recover_depth.h"

namespace corridor {

// geometry.csv: a header row, then `frame,status,yaw,pitch,offset,width,ceiling_height,seconds`
// per frame; radians and metres with the signs of geometry.md; status "ok" or the error; an
// unknown value is empty.
class GeometryCsv {
 public:
  void Add(const std::string& frame, const RecoverDepthResult& result);
  void AddFailure(const std::string& frame, const Status& status);
  std::string Text() const;
  int size() const { return static_cast<int>(rows_.size()); }

 private:
  std::vector<std::string> rows_;
};

// Quotes a CSV field when it holds a comma, quote or newline.
std::string CsvField(const std::string& text);

}  // namespace corridor
