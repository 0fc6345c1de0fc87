#include "corridor_depth/status.h"

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
    case StatusCode::kLowConfidence:
      return "low confidence";
    case StatusCode::kInternal:
      return "internal error";
  }
  return "unknown";
}

const char* StatusCodeName(StatusCode code) {
  switch (code) {
    case StatusCode::kOk:
      return "ok";
    case StatusCode::kInvalidArgument:
      return "invalid_argument";
    case StatusCode::kNotFound:
      return "not_found";
    case StatusCode::kIoError:
      return "io_error";
    case StatusCode::kNoCorridorFound:
      return "no_corridor_found";
    case StatusCode::kImplausibleGeometry:
      return "implausible_geometry";
    case StatusCode::kLowConfidence:
      return "low_confidence";
    case StatusCode::kInternal:
      break;
  }
  return "internal";
}

const char* StatusClass(StatusCode code) {
  switch (code) {
    case StatusCode::kOk:
      return "ok";
    case StatusCode::kNoCorridorFound:
    case StatusCode::kImplausibleGeometry:
    case StatusCode::kLowConfidence:
      return "refused";
    case StatusCode::kInvalidArgument:
    case StatusCode::kNotFound:
    case StatusCode::kIoError:
    case StatusCode::kInternal:
      break;
  }
  return "failed";
}

std::string Status::ToString() const {
  if (ok()) return "ok";
  return std::string(StatusCodeToString(code_)) + ": " + message_;
}

}  // namespace corridor
