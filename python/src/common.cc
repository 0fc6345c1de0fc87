#include "python/src/common.h"

#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

namespace corridor {
namespace python {
namespace {

// 0, negative and non-finite depths -> NaN, in place. Branch-free so that it vectorises (NaN
// compares false, so NaN stays NaN); with AVX2 where the CPU has it, as this pass is most of
// what the binding adds to a frame.
__attribute__((target_clones("avx2", "default"))) void MarkNoEstimate(float* pixels, size_t n) {
  const float none = std::numeric_limits<float>::quiet_NaN();
  const float largest = std::numeric_limits<float>::max();
  for (size_t i = 0; i < n; ++i) {
    const float d = pixels[i];
    pixels[i] = d > 0.0f && d <= largest ? d : none;
  }
}

}  // namespace

void ThrowStatus(const Status& status) {
  switch (status.code()) {
    case StatusCode::kInvalidArgument:
      throw py::value_error(status.message());
    case StatusCode::kNotFound:
      PyErr_SetString(PyExc_FileNotFoundError, status.message().c_str());
      throw py::error_already_set();
    case StatusCode::kIoError:
      PyErr_SetString(PyExc_OSError, status.message().c_str());
      throw py::error_already_set();
    default:
      throw std::runtime_error(status.ToString());
  }
}

bool IsCallerError(const Status& status) {
  return status.code() == StatusCode::kInvalidArgument || status.code() == StatusCode::kNotFound ||
         status.code() == StatusCode::kIoError;
}

const char* StatusClassName(const Status& status) { return StatusClass(status.code()); }

ImageInput ImageFromArray(const py::handle& image, bool rgb) {
  if (!py::isinstance<py::array>(image)) {
    throw py::value_error("image must be a numpy array (uint8 HxWx3 BGR or HxW grey), not " +
                          std::string(py::str(py::type::of(image))));
  }
  ImageInput input;
  input.holder = py::array::ensure(image, py::array::c_style);
  const py::array& a = input.holder;
  int depth = -1;
  if (a.dtype().is(py::dtype::of<uint8_t>())) depth = CV_8U;
  if (a.dtype().is(py::dtype::of<uint16_t>())) depth = CV_16U;
  if (depth < 0) {
    throw py::value_error("image must be uint8 or uint16, not " + std::string(py::str(a.dtype())));
  }
  const int channels = a.ndim() == 2 ? 1 : a.ndim() == 3 ? static_cast<int>(a.shape(2))
                                                         : 0;
  if (channels != 1 && channels != 3 && channels != 4) {
    throw py::value_error("image must be HxW, HxWx3 or HxWx4, not of shape " +
                          std::string(py::str(py::getattr(image, "shape"))));
  }
  if (a.shape(0) == 0 || a.shape(1) == 0) throw py::value_error("image is empty");
  input.mat = cv::Mat(static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)),
                      CV_MAKETYPE(depth, channels), const_cast<void*>(a.data()));
  if (rgb && channels == 3) {
    cv::Mat bgr;
    cv::cvtColor(input.mat, bgr, cv::COLOR_RGB2BGR);
    input.mat = bgr;
  } else if (rgb && channels == 4) {
    cv::Mat bgra;
    cv::cvtColor(input.mat, bgra, cv::COLOR_RGBA2BGRA);
    input.mat = bgra;
  }
  return input;
}

py::array ArrayFromImage(const cv::Mat& image) {
  const py::dtype dtype =
      image.depth() == CV_16U ? py::dtype::of<uint16_t>() : py::dtype::of<uint8_t>();
  std::vector<py::ssize_t> shape = {image.rows, image.cols};
  if (image.channels() > 1) shape.push_back(image.channels());
  py::array out(dtype, shape);
  cv::Mat view(image.rows, image.cols, image.type(), out.mutable_data());
  image.copyTo(view);
  return out;
}

py::array_t<float> DepthToArray(cv::Mat&& depth, int rows, int cols) {
  const float none = std::numeric_limits<float>::quiet_NaN();
  if (depth.empty() || depth.type() != CV_32FC1) {
    depth = cv::Mat(rows, cols, CV_32FC1, cv::Scalar(none));
  } else if (!depth.isContinuous() || (depth.u != nullptr && depth.u->refcount > 1)) {
    depth = depth.clone();  // Not changed where another holder could see it.
  }
  MarkNoEstimate(depth.ptr<float>(), depth.total());
  auto* owner = new cv::Mat(std::move(depth));
  const py::capsule base(owner, [](void* p) { delete static_cast<cv::Mat*>(p); });
  return py::array_t<float>({owner->rows, owner->cols}, owner->ptr<float>(), base);
}

std::vector<Eigen::Vector2d> PointsFromArray(const py::handle& points, const char* what) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.ndim() != 2 || a.shape(1) != 2) {
    throw py::value_error(std::string(what) + " must be an N x 2 array of pixel coordinates");
  }
  std::vector<Eigen::Vector2d> out(static_cast<size_t>(a.shape(0)));
  for (size_t i = 0; i < out.size(); ++i) out[i] = {a.at(i, 0), a.at(i, 1)};
  return out;
}

std::vector<Eigen::Vector2d> Undistorted(const std::vector<Eigen::Vector2d>& raw,
                                         const Camera& camera) {
  std::vector<Eigen::Vector2d> out;
  out.reserve(raw.size());
  for (const auto& p : raw) out.push_back(camera.Undistort(p));
  return out;
}

Camera WithHeight(const Camera& camera, const py::object& height) {
  Camera out = camera;
  if (!height.is_none()) {
    out.mount_height = py::cast<double>(height);
    std::string why;
    if (!out.Check(&why)) throw py::value_error("camera_height: " + why);
  } else if (!(camera.mount_height > 0)) {
    throw py::value_error(
        "camera_height is required: the camera carries no height above the floor");
  }
  return out;
}

py::tuple Tuple(const Eigen::Vector2d& v) { return py::make_tuple(v.x(), v.y()); }

}  // namespace python
}  // namespace corridor
