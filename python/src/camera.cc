// Camera, read_image and write_depth_png.

#include <cmath>
#include <sstream>

#include <pybind11/stl.h>

#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/image_io.h"
#include "python/src/bindings.h"
#include "python/src/common.h"

namespace corridor {
namespace python {
namespace {

Camera Checked(const Camera& camera) {
  std::string why;
  if (!camera.CheckIntrinsics(&why)) throw py::value_error("camera: " + why);
  if (camera.mount_height != 0 && !camera.Check(&why)) throw py::value_error("camera: " + why);
  return camera;
}

Camera FromIntrinsics(double fx, double fy, double cx, double cy, int width, int height,
                      const std::vector<double>& distortion, double camera_height) {
  Camera camera;
  camera.fx = fx;
  camera.fy = fy;
  camera.cx = cx;
  camera.cy = cy;
  camera.image_width = width;
  camera.image_height = height;
  if (!distortion.empty() && distortion.size() != 5) {
    throw py::value_error("distortion must hold 5 plumb_bob coefficients (k1, k2, p1, p2, k3)");
  }
  for (size_t i = 0; i < distortion.size(); ++i) camera.distortion[i] = distortion[i];
  camera.mount_height = camera_height;
  return Checked(camera);
}

std::string Repr(const Camera& c) {
  std::ostringstream out;
  out << "Camera(fx=" << c.fx << ", fy=" << c.fy << ", cx=" << c.cx << ", cy=" << c.cy
      << ", width=" << c.image_width << ", height=" << c.image_height
      << ", camera_height=" << c.mount_height << ")";
  return out.str();
}

}  // namespace

void BindCamera(py::module_& m) {
  py::class_<Camera>(m, "Camera",
                     "A pinhole camera (pixels) with optional plumb_bob distortion and its height "
                     "above the floor (camera_height, metres; 0 = not known).")
      .def(py::init(&FromIntrinsics), py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"),
           py::arg("image_width"), py::arg("image_height"), py::kw_only(),
           py::arg("distortion") = std::vector<double>(), py::arg("camera_height") = 0.0)
      .def_static(
          "from_hfov",
          [](double hfov_deg, int width, int height, double camera_height) {
            if (!(hfov_deg > 0 && hfov_deg < 180)) {
              throw py::value_error("hfov must be in (0, 180) degrees");
            }
            return Checked(Camera::FromHorizontalFov(width, height, hfov_deg * M_PI / 180.0,
                                                     camera_height));
          },
          py::arg("hfov"), py::arg("image_width"), py::arg("image_height"), py::kw_only(),
          py::arg("camera_height") = 0.0,
          "A camera from a horizontal field of view in degrees, principal point at the centre.")
      .def_static(
          "from_file",
          [](const std::string& path) {
            Camera camera;
            ThrowIfError(ReadCameraYaml(path, &camera));
            return camera;
          },
          py::arg("path"),
          "A camera from a ROS camera_info YAML with the extra key camera_height (metres).")
      .def_readwrite("fx", &Camera::fx)
      .def_readwrite("fy", &Camera::fy)
      .def_readwrite("cx", &Camera::cx)
      .def_readwrite("cy", &Camera::cy)
      .def_readwrite("image_width", &Camera::image_width)
      .def_readwrite("image_height", &Camera::image_height)
      .def_readwrite("camera_height", &Camera::mount_height)
      .def_property(
          "distortion", [](const Camera& c) { return c.distortion; },
          [](Camera& c, const std::array<double, 5>& d) { c.distortion = d; })
      .def_property_readonly(
          "hfov",
          [](const Camera& c) {
            return 2.0 * std::atan(0.5 * c.image_width / c.fx) * 180.0 / M_PI;
          },
          "Horizontal field of view, degrees.")
      .def("__repr__", &Repr);

  m.def(
      "read_image",
      [](const std::string& path, bool upright) {
        cv::Mat bgr;
        ThrowIfError(ReadColorImage(
            path, &bgr, upright ? ImageOrientation::kUpright : ImageOrientation::kAsStored));
        return ArrayFromImage(bgr);
      },
      py::arg("path"), py::kw_only(), py::arg("upright") = false,
      "Reads any colour, grey, 16-bit or alpha image as uint8 HxWx3 BGR, as the tools do: the "
      "pixels as stored (a calibration is for these), or with upright=True turned as a photo's "
      "EXIF orientation says.");
  m.def(
      "write_depth_png",
      [](const std::string& path, const py::array_t<float, py::array::c_style |
                                                               py::array::forcecast>& depth) {
        if (depth.ndim() != 2) throw py::value_error("depth must be an HxW array of metres");
        const cv::Mat view(static_cast<int>(depth.shape(0)), static_cast<int>(depth.shape(1)),
                           CV_32FC1, const_cast<float*>(depth.data()));
        ThrowIfError(WriteDepthPng(path, view));
      },
      py::arg("path"), py::arg("depth"),
      "Writes depth in metres as the tools do: a 16-bit PNG in millimetres, 0 = no estimate "
      "(NaN).");
}

}  // namespace python
}  // namespace corridor
