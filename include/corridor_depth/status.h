#pragma once

#include <string>
#include <utility>

namespace corridor {

// What went wrong, coarse enough for a caller to branch on.
enum class StatusCode {
  kOk = 0,
  kInvalidArgument,      // Bad options, calibration or image (the caller's input).
  kNotFound,             // A file or folder that is not there.
  kIoError,              // A file that exists but cannot be read or written.
  kNoCorridorFound,      // The image holds no usable pair of junction lines.
  kImplausibleGeometry,  // The lines were found, but the geometry they give is not a corridor.
  kLowConfidence,        // A plausible corridor, but the evidence for it is too weak to trust.
  kInternal,             // A numerical failure that no input should cause.
};

const char* StatusCodeToString(StatusCode code);
// The code as one snake_case word, for files and logs: "no_corridor_found", "io_error", ...
const char* StatusCodeName(StatusCode code);

// What a frame's status means to its user: "ok" (depth recovered), "refused" (the image was read
// but its corridor could not be trusted: none found, implausible, low confidence) or "failed" (a
// bad input, a missing or unreadable file, an internal error).
const char* StatusClass(StatusCode code);

// A result code with a human-readable message. Cheap to copy; no exceptions.
class Status {
 public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}

  static Status Ok() { return Status(); }
  static Status InvalidArgument(std::string m) { return {StatusCode::kInvalidArgument, std::move(m)}; }
  static Status NotFound(std::string m) { return {StatusCode::kNotFound, std::move(m)}; }
  static Status IoError(std::string m) { return {StatusCode::kIoError, std::move(m)}; }
  static Status NoCorridorFound(std::string m) { return {StatusCode::kNoCorridorFound, std::move(m)}; }
  static Status ImplausibleGeometry(std::string m) {
    return {StatusCode::kImplausibleGeometry, std::move(m)};
  }
  static Status LowConfidence(std::string m) { return {StatusCode::kLowConfidence, std::move(m)}; }
  static Status Internal(std::string m) { return {StatusCode::kInternal, std::move(m)}; }

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }
  // "ok", or "<code>: <message>".
  std::string ToString() const;

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

}  // namespace corridor
