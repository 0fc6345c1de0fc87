#pragma once

// Turns a fuzzer's bytes into one RecoverDepth call: a small image (at most 64x64, 1-4 channels,
// 8- or 16-bit), a camera, RecoverDepthOptions with names and numbers taken from the bytes
// (including empty, unknown, zero, negative, NaN and infinite values, which Check must reject),
// and optionally a pair of junction lines to reconstruct from directly, so that the solvers and
// rasterisers see arbitrary lines even when perception finds none in noise. Shared by the
// libFuzzer target (fuzz_recover_depth.cc) and the regression tests that replay its findings.
//
// Layout: a 32-byte header (missing bytes read as 0), then pixel bytes repeated over the image.
//   [0] width-1 (mod 64)   [1] height-1 (mod 64)
//   [2] bits 0-1 channels-1, bit 2 16-bit, bit 3 camera one pixel wider than the image,
//       bit 4 reconstruct the junctions of [19..26], bit 5 distortion from [18]
//   [3] solver name   [4] rasteriser name   [5] loss name   [6] points_per_line + 20
//   [7..14] min_width, max_width, roi_top_fraction, max_range, grid yaw_step, hough_max_gap,
//           blur_sigma, ceiling_height   [15..18] fx, cx, camera height, k1
//   [19..26] left near/far and right near/far ends (u, v)   [27..29] paper_planes, lm
//   max_iterations, grid refinement_levels   [30..31] unused
// The grid is coarser than the default (see below) to keep every input fast.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {
namespace fuzz {

constexpr size_t kHeaderBytes = 32;
constexpr int kMaxSide = 64;

struct FuzzCase {
  cv::Mat image;
  Camera camera;
  RecoverDepthOptions options;
  bool reconstruct = false;  // Also run Reconstruct on `junctions`.
  JunctionPair junctions;
};

// A value from a selector byte: the low 3 bits pick the default, 0, a negative value, NaN,
// infinity, a huge or a tiny value, or (7) the default scaled by (byte >> 3) / 8.
inline double Pick(uint8_t b, double normal) {
  switch (b & 7) {
    case 0:
      return normal;
    case 1:
      return 0.0;
    case 2:
      return -normal - 1.0;
    case 3:
      return std::numeric_limits<double>::quiet_NaN();
    case 4:
      return std::numeric_limits<double>::infinity();
    case 5:
      return 1e300;
    case 6:
      return 1e-300;
    default:
      return normal * (b >> 3) / 8.0;
  }
}

inline FuzzCase DecodeFuzzInput(const uint8_t* data, size_t size) {
  uint8_t h[kHeaderBytes] = {};
  for (size_t i = 0; i < kHeaderBytes && i < size; ++i) h[i] = data[i];
  const uint8_t* pixels = size > kHeaderBytes ? data + kHeaderBytes : nullptr;
  const size_t num_pixels = size > kHeaderBytes ? size - kHeaderBytes : 0;

  FuzzCase c;
  const int width = 1 + h[0] % kMaxSide, height = 1 + h[1] % kMaxSide;
  const int channels = 1 + (h[2] & 3);
  const bool sixteen = (h[2] & 4) != 0;
  c.image.create(height, width, CV_MAKETYPE(sixteen ? CV_16U : CV_8U, channels));
  const size_t bytes = c.image.total() * c.image.elemSize();
  uint8_t* out = c.image.ptr<uint8_t>();  // Continuous: freshly created.
  for (size_t i = 0; i < bytes; ++i) out[i] = num_pixels > 0 ? pixels[i % num_pixels] : 0;

  static const char* const kSolvers[] = {"closed_form+lm", "grid", "closed_form", "lm", "joint",
                                         "closed_form+joint", "", "bogus", "lm+", "+grid"};
  static const char* const kRasterizers[] = {"exact", "paper", "", "Exact", "paper+"};
  static const char* const kLosses[] = {"huber", "none", "cauchy", "squared"};
  RecoverDepthOptions& o = c.options;
  o.solver = kSolvers[h[3] % 10];
  o.rasterizer = kRasterizers[h[4] % 5];
  o.solver_options.loss = kLosses[h[5] % 4];
  o.points_per_line = static_cast<int>(h[6]) - 20;
  o.min_width = Pick(h[7], o.min_width);
  o.max_width = Pick(h[8], o.max_width);
  o.perception.roi_top_fraction = Pick(h[9], o.perception.roi_top_fraction);
  o.rasterizer_options.max_range = Pick(h[10], o.rasterizer_options.max_range);
  o.solver_options.grid.yaw_step = Pick(h[11], o.solver_options.grid.yaw_step);
  o.perception.hough_max_gap = Pick(h[12], o.perception.hough_max_gap);
  o.perception.blur_sigma = Pick(h[13], o.perception.blur_sigma);
  o.ceiling_height = Pick(h[14], 0.0) + ((h[14] & 7) == 7 ? 2.6 : 0.0);
  o.rasterizer_options.paper_planes = static_cast<int>(h[27]) * 2 - 8;
  o.solver_options.lm.max_iterations = static_cast<int>(h[28] % 64) - 2;
  o.solver_options.grid.refinement_levels = static_cast<int>(h[29] % 12) - 1;
  // A coarse grid, so that a grid input costs about as much as the others (the fuzzer looks for
  // crashes and broken contracts, not for accuracy).
  o.solver_options.grid.pitch_step = 0.1;
  o.solver_options.grid.offset_step = 0.25;
  o.solver_options.grid.width_step = 0.25;
  o.solver_options.max_rounds = 4;

  Camera& cam = c.camera;
  cam.image_width = width + ((h[2] & 8) != 0 ? 1 : 0);
  cam.image_height = height;
  cam.fx = cam.fy = Pick(h[15], 0.8 * width);
  cam.cx = Pick(h[16], 0.5 * (width - 1));
  cam.cy = 0.5 * (height - 1);
  cam.mount_height = Pick(h[17], 1.2);
  if ((h[2] & 32) != 0) cam.distortion[0] = Pick(h[18], 0.1) * ((h[18] & 128) != 0 ? -1 : 1);

  c.reconstruct = (h[2] & 16) != 0;
  if (c.reconstruct) {
    // Ends in [-width/2, 3 width/2] x [-height/2, 3 height/2]: inside and outside the image.
    const auto end = [&](int i) {
      return Eigen::Vector2d((h[i] / 127.5 - 0.5) * width, (h[i + 1] / 127.5 - 0.5) * height);
    };
    JunctionLine* lines[2] = {&c.junctions.left, &c.junctions.right};
    for (int side = 0; side < 2; ++side) {
      JunctionLine& line = *lines[side];
      line.near_end = end(19 + 4 * side);
      line.far_end = end(21 + 4 * side);
      const Eigen::Vector2d d = line.far_end - line.near_end;
      const double n = d.norm();
      if (n > 0) {
        line.line = Eigen::Vector3d(-d.y() / n, d.x() / n, 0);
        line.line.z() = -line.line.head<2>().dot(line.near_end);
      }
      line.confidence = 1.0;
    }
  }
  return c;
}

// The bytes of a case with an image from the caller (8-bit BGR, at most 64x64) and default
// options, for seed corpora: the inverse of DecodeFuzzInput for that subset.
inline std::string EncodeFuzzSeed(const cv::Mat& bgr, uint8_t solver, uint8_t rasterizer) {
  std::string bytes(kHeaderBytes, '\0');
  bytes[0] = static_cast<char>(bgr.cols - 1);
  bytes[1] = static_cast<char>(bgr.rows - 1);
  bytes[2] = static_cast<char>(bgr.channels() - 1);
  bytes[3] = static_cast<char>(solver);
  bytes[4] = static_cast<char>(rasterizer);
  bytes[6] = static_cast<char>(30 + 20);        // points_per_line 30.
  bytes[27] = static_cast<char>((96 + 8) / 2);  // paper_planes 96.
  bytes[28] = static_cast<char>(50 + 2);        // lm max_iterations 50.
  bytes[29] = static_cast<char>(2 + 1);         // refinement_levels 2.
  const cv::Mat continuous = bgr.isContinuous() ? bgr : bgr.clone();
  bytes.append(reinterpret_cast<const char*>(continuous.data),
               continuous.total() * continuous.elemSize());
  return bytes;
}

}  // namespace fuzz
}  // namespace corridor
