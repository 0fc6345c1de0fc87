// Status, Geometry, JunctionLine, Junctions, Result and recover_depth.

#include <sstream>

#include <pybind11/stl.h>

#include "python/src/bindings.h"
#include "python/src/common.h"
#include "python/src/options.h"
#include "python/src/result.h"

namespace corridor {
namespace python {
namespace {

PyResult RecoverDepthPy(const py::handle& image, const Camera& camera, bool rgb,
                        const py::kwargs& kwargs) {
  py::object height;
  const RecoverDepthOptions options = OptionsFromKwargs(kwargs, &height);
  const Camera with_height = WithHeight(camera, height);
  const ImageInput input = ImageFromArray(image, rgb);
  std::unique_ptr<DepthRecoverer> recoverer;
  ThrowIfError(DepthRecoverer::Create(options, &recoverer));
  RecoverDepthResult result;
  {
    py::gil_scoped_release release;
    recoverer->Recover(input.mat, with_height, &result);
  }
  return MakeResult(std::move(result), input.mat.rows, input.mat.cols);
}

py::dict Times(const StageTimes& t) {
  py::dict d;
  d["perception"] = t.perception;
  d["solve"] = t.solve;
  d["ceiling"] = t.ceiling;
  d["end_wall"] = t.end_wall;
  d["rasterize"] = t.rasterize;
  d["total"] = t.total;
  return d;
}

}  // namespace

void BindRecover(py::module_& m) {
  py::class_<Status>(m, "Status", "Why a frame has no depth, or ok.")
      .def_property_readonly("ok", &Status::ok)
      .def_property_readonly(
          "code", [](const Status& s) { return StatusCodeName(s.code()); },
          "E.g. 'ok', 'no_corridor_found', 'low_confidence', 'invalid_argument'.")
      .def_property_readonly("message", &Status::message)
      .def_property_readonly("status_class", &StatusClassName,
                             "'ok', 'refused' (no corridor, implausible geometry, low confidence) or 'failed'.")
      .def("__str__", &Status::ToString)
      .def("__repr__", [](const Status& s) { return "<Status " + s.ToString() + ">"; });

  py::class_<CorridorGeometry>(m, "Geometry",
                               "The straight-corridor model: radians and metres (geometry.md).")
      .def(py::init([](double yaw, double pitch, double offset, double width,
                       double camera_height, double ceiling_height) {
             CorridorGeometry g;
             g.yaw = yaw;
             g.pitch = pitch;
             g.offset = offset;
             g.width = width;
             g.camera_height = camera_height;
             g.ceiling_height = ceiling_height;
             return g;
           }),
           py::kw_only(), py::arg("yaw") = 0.0, py::arg("pitch") = 0.0, py::arg("offset") = 0.0,
           py::arg("width") = 0.0, py::arg("camera_height") = 0.0,
           py::arg("ceiling_height") = 0.0)
      .def_readwrite("yaw", &CorridorGeometry::yaw, "> 0 when the corridor axis appears right of cx")
      .def_readwrite("pitch", &CorridorGeometry::pitch, "> 0 when the camera is pitched down")
      .def_readwrite("offset", &CorridorGeometry::offset,
                     "(d_l - d_r) / 2: > 0 when the camera is right of the centre line")
      .def_readwrite("width", &CorridorGeometry::width)
      .def_readwrite("camera_height", &CorridorGeometry::camera_height)
      .def_readwrite("ceiling_height", &CorridorGeometry::ceiling_height, "0 = unknown")
      .def_readwrite("end_distance", &CorridorGeometry::end_distance, "0 = no end wall seen")
      .def_property_readonly("left_distance", &CorridorGeometry::LeftDistance)
      .def_property_readonly("right_distance", &CorridorGeometry::RightDistance)
      .def("__repr__", [](const CorridorGeometry& g) { return "<Geometry " + g.ToString() + ">"; });

  py::class_<JunctionLine>(m, "JunctionLine", "A floor/wall junction line in raw image pixels.")
      .def_property_readonly(
          "line",
          [](const JunctionLine& l) {
            return py::make_tuple(l.line.x(), l.line.y(), l.line.z());
          },
          "(a, b, c) with a u + b v + c = 0 and a^2 + b^2 = 1.")
      .def_property_readonly(
          "near_end", [](const JunctionLine& l) { return Tuple(l.near_end); },
          "(u, v) of the supported end nearest the camera.")
      .def_property_readonly(
          "far_end", [](const JunctionLine& l) { return Tuple(l.far_end); },
          "(u, v) of the supported end toward the vanishing point.")
      .def_readonly("support_length", &JunctionLine::support_length)
      .def_readonly("confidence", &JunctionLine::confidence)
      .def_property_readonly(
          "edge_points",
          [](const JunctionLine& l) {
            py::array_t<double> points({static_cast<py::ssize_t>(l.edge_points.size()),
                                        static_cast<py::ssize_t>(2)});
            auto out = points.mutable_unchecked<2>();
            for (size_t i = 0; i < l.edge_points.size(); ++i) {
              out(i, 0) = l.edge_points[i].x();
              out(i, 1) = l.edge_points[i].y();
            }
            return points;
          },
          "N x 2 float64 (u, v), raw pixels: the sub-pixel edge points the solver fitted "
          "(solver_evidence 'edges'); 0 x 2 when it fitted points on the line.")
      .def_property_readonly(
          "edge_weights",
          [](const JunctionLine& l) {
            return py::array_t<double>(static_cast<py::ssize_t>(l.edge_weights.size()),
                                       l.edge_weights.data());
          },
          "N float64: one weight per edge point (mean 1).");

  py::class_<JunctionPair>(m, "Junctions", "Both junction lines as detected.")
      .def_property_readonly("found", [](const JunctionPair& j) { return j.status.ok(); })
      .def_readonly("left", &JunctionPair::left)
      .def_readonly("right", &JunctionPair::right)
      .def_property_readonly("vanishing_point",
                             [](const JunctionPair& j) { return Tuple(j.vanishing_point); })
      .def_readonly("has_single", &JunctionPair::has_single,
                    "Only one junction seen (then `single`, on the side `single_is_left`).")
      .def_readonly("single_is_left", &JunctionPair::single_is_left)
      .def_readonly("single", &JunctionPair::single);

  py::class_<PyResult>(m, "Result", "One frame's depth, geometry and junctions.")
      .def_property_readonly("ok", [](const PyResult& r) { return r.status.ok(); })
      .def_readonly("status", &PyResult::status)
      .def_readonly("depth", &PyResult::depth, "float32 HxW, metres, NaN = no estimate")
      .def_readonly("confidence", &PyResult::confidence,
                    "In [0, 1]: the evidence for the layout (0 without one); frames below the "
                    "min_confidence keyword are refused with code 'low_confidence'.")
      .def_readonly("roll", &PyResult::roll,
                    "Radians: the camera's roll the frame was recovered level from (0 when none "
                    "was found, or with level_roll=False); `geometry` is then the level camera's.")
      .def_readonly("has_geometry", &PyResult::has_geometry)
      .def_readonly("geometry", &PyResult::geometry)
      .def_readonly("junctions", &PyResult::junctions)
      .def_readonly("solver_summary", &PyResult::solver_summary)
      .def_readonly("ceiling_found", &PyResult::ceiling_found)
      .def_readonly("end_wall_found", &PyResult::end_wall_found)
      .def_readonly("fallback", &PyResult::fallback)
      .def_readonly("width_held", &PyResult::width_held)
      .def_readonly("walls_scaled", &PyResult::walls_scaled)
      .def_readonly("ceiling_held", &PyResult::ceiling_held)
      .def_readonly("junctions_tracked", &PyResult::junctions_tracked)
      .def_readonly("ceiling_trusted", &PyResult::ceiling_trusted)
      .def_property_readonly(
          "times", [](const PyResult& r) { return Times(r.times); },
          "Wall time of each stage, seconds.")
      .def("__repr__", [](const PyResult& r) {
        std::ostringstream out;
        out << "<Result " << r.status.ToString();
        if (r.has_geometry) out << " " << r.geometry.ToString();
        out << ">";
        return out.str();
      });

  m.def("recover_depth", &RecoverDepthPy, py::arg("image"), py::arg("camera"), py::kw_only(),
        py::arg("rgb") = false,
        "Depth of one corridor image.\n\n"
        "image: uint8 HxWx3 BGR (rgb=True: RGB), HxWx4, or HxW grey, of the camera's size.\n"
        "camera_height: metres above the floor; overrides the camera's, required when it has "
        "none.\nOther keywords: the RecoverDepthOptions fields and the tools' flag names "
        "(solver, rasterizer, max_range, min_confidence, ...; see option_names()).\n"
        "A frame without a corridor returns a Result with ok False; a bad input raises "
        "ValueError with the message.");
  m.def("option_names", &OptionNames, "The option keywords recover_depth and Sequence take.");
}

}  // namespace python
}  // namespace corridor
