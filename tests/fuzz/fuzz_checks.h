#pragma once

// The contracts the fuzz targets check on each input, shared with the regression tests that
// replay the fuzzers' findings (tests/reliability/fuzz_regression_test.cc). Each returns "" when
// every contract holds, else which one broke. Sanitizer findings (ASan, UBSan) come on top.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "corridor_depth/camera.h"
#include "corridor_depth/camera_yaml.h"
#include "pipeline/plausibility.h"
#include "corridor_depth/recover_depth.h"
#include "tests/fuzz/fuzz_input.h"

namespace corridor {
namespace fuzz {

// A finished frame: failed with a message and no depth, or plausible geometry and a finite,
// non-negative CV_32F depth of the camera's size.
inline std::string CheckResult(const Camera& camera, const RecoverDepthOptions& options,
                               const RecoverDepthResult& result) {
  if (!result.status.ok()) {
    if (result.status.message().empty()) return "a failure without a message";
    if (!result.depth.empty()) return "a failed frame has depth: " + result.status.ToString();
    return "";
  }
  if (!result.has_geometry) return "ok without geometry";
  if (!CheckPlausible(result.geometry, options).ok()) return "ok with implausible geometry";
  if (result.depth.type() != CV_32FC1) return "depth is not CV_32FC1";
  if (result.depth.cols != camera.image_width || result.depth.rows != camera.image_height) {
    return "depth is not the camera's size";
  }
  for (int r = 0; r < result.depth.rows; ++r) {
    const float* row = result.depth.ptr<float>(r);
    for (int c = 0; c < result.depth.cols; ++c) {
      // NaN = no estimate; every estimate is a positive, finite depth.
      if (!std::isnan(row[c]) && !(std::isfinite(row[c]) && row[c] > 0)) {
        return "depth not positive, finite or NaN";
      }
    }
  }
  return "";
}

// fuzz_recover_depth: options that fail Check are rejected with InvalidArgument by Create and by
// RecoverDepth, before any work; every result keeps CheckResult's contract, also when the
// junctions come straight from the bytes (Reconstruct).
inline std::string CheckRecoverDepthInput(const uint8_t* data, size_t size) {
  const FuzzCase c = DecodeFuzzInput(data, size);
  const bool options_ok = c.options.Check(nullptr);
  std::unique_ptr<DepthRecoverer> recoverer;
  const Status created = DepthRecoverer::Create(c.options, &recoverer);
  if (!options_ok && created.code() != StatusCode::kInvalidArgument) {
    return "options that fail Check were not rejected: " + created.ToString();
  }
  if (!created.ok() && created.code() != StatusCode::kInvalidArgument) {
    return "Create failed with " + created.ToString();
  }
  RecoverDepthResult result;
  const Status status = RecoverDepth(c.image, c.camera, c.options, &result);
  if (!created.ok()) {
    if (status.code() != StatusCode::kInvalidArgument || !result.depth.empty() ||
        result.times.perception != 0) {
      return "RecoverDepth did work with rejected options: " + status.ToString();
    }
    return "";
  }
  std::string broken = CheckResult(c.camera, c.options, result);
  if (!broken.empty() || !c.reconstruct || !c.camera.Check(nullptr)) return broken;
  RecoverDepthResult direct;
  direct.junctions = c.junctions;
  recoverer->Reconstruct(c.camera, &direct);
  broken = CheckResult(c.camera, c.options, direct);
  return broken.empty() ? "" : "Reconstruct: " + broken;
}

// fuzz_camera_yaml: every error names the file; every accepted camera passes CheckIntrinsics and
// maps its image corners through Undistort and Distort.
inline std::string CheckCameraYamlInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Camera camera;
  const Status status = ParseCameraYaml(text, "fuzz.yaml", &camera);
  if (!status.ok()) {
    if (status.message().find("fuzz.yaml") == std::string::npos) {
      return "an error that does not name the file: " + status.ToString();
    }
    return "";
  }
  if (!camera.CheckIntrinsics(nullptr)) return "accepted a camera that fails CheckIntrinsics";
  for (const Eigen::Vector2d& corner :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(camera.image_width - 1, camera.image_height - 1)}) {
    camera.Distort(camera.Undistort(corner));
  }
  return "";
}

}  // namespace fuzz
}  // namespace corridor
