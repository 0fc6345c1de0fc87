#pragma once

// Shared helpers of the Python module: statuses to exceptions, numpy arrays to and from cv::Mat
// and point lists.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"

namespace corridor {
namespace python {

namespace py = pybind11;

// Raises the exception for a failed status, carrying its message: ValueError (invalid argument),
// FileNotFoundError (not found), OSError (i/o error), RuntimeError (anything else).
[[noreturn]] void ThrowStatus(const Status& status);
inline void ThrowIfError(const Status& status) {
  if (!status.ok()) ThrowStatus(status);
}
// A caller's mistake rather than a frame's outcome: invalid argument, not found, i/o error.
bool IsCallerError(const Status& status);
// "ok", "refused" (no corridor, implausible geometry, low confidence) or "failed" (StatusClass).
const char* StatusClassName(const Status& status);

// An image given as a numpy array: uint8 or uint16, HxW (grey), HxWx3 (BGR, or RGB with `rgb`)
// or HxWx4 (BGRA / RGBA). `mat` views `holder`'s memory (a C-contiguous array; the input itself
// when it is one), or owns its own copy when the channels were swapped. ValueError otherwise.
struct ImageInput {
  py::array holder;
  cv::Mat mat;
};
ImageInput ImageFromArray(const py::handle& image, bool rgb);

// An 8-bit or 16-bit image as a numpy array (HxW or HxWxC), copied.
py::array ArrayFromImage(const cv::Mat& image);

// A CV_32F depth image as a float32 HxW array in metres with NaN where there is no estimate (0,
// negative or non-finite in `depth`); all NaN of rows x cols when `depth` is empty. The array
// takes over `depth`'s pixels (no copy) and marks "no estimate" in place.
py::array_t<float> DepthToArray(cv::Mat&& depth, int rows, int cols);

// An array-like of N points (N x 2, pixels) as points; ValueError naming `what` otherwise.
std::vector<Eigen::Vector2d> PointsFromArray(const py::handle& points, const char* what);
// Raw image pixels to ideal ones through the camera's distortion (identity without).
std::vector<Eigen::Vector2d> Undistorted(const std::vector<Eigen::Vector2d>& raw,
                                         const Camera& camera);

// A camera with the given height (camera_height), or the camera's own when `height` is None;
// ValueError when neither gives a positive height.
Camera WithHeight(const Camera& camera, const py::object& height);

py::tuple Tuple(const Eigen::Vector2d& v);

}  // namespace python
}  // namespace corridor
