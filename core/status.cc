#include "core/status.h"

namespace corridor {

const char* StatusCodeToString(StatusCode code) {
  switch (code) {
    case StatusCode::kOk:
      return "ok";
    case StatusCode::kInvalidArgument:
      return "invalid argument";
    case StatusCode::kNotFound:
      return "not found";
    case StatusCode::kIoError:
      return "i/o error";
    case StatusCode::kNoCorridorFound:
      return "no corridor found";
    case StatusCode::kImplausibleGeometry:
      return "implausible geometry";
    case StatusCode::kInternal:
      return "internal error";
  }
  return "unknown";
}

std::string Status::ToString() const {
  if (ok()) return "ok";
  return std::string(StatusCodeToString(code_)) + ": " + message_;
}

}  // namespace corridor
