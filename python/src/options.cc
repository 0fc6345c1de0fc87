#include "python/src/options.h"

#include <functional>
#include <map>

#include "python/src/common.h"

namespace corridor {
namespace python {
namespace {

using Setter = std::function<void(RecoverDepthOptions*, const py::handle&)>;

template <typename T>
Setter Field(T RecoverDepthOptions::*field) {
  return [field](RecoverDepthOptions* o, const py::handle& v) { o->*field = py::cast<T>(v); };
}
template <typename S, typename T>
Setter Nested(S RecoverDepthOptions::*group, T S::*field) {
  return [group, field](RecoverDepthOptions* o, const py::handle& v) {
    (o->*group).*field = py::cast<T>(v);
  };
}

const std::map<std::string, Setter>& Setters() {
  static const std::map<std::string, Setter> setters = [] {
    using O = RecoverDepthOptions;
    std::map<std::string, Setter> s;
    // RecoverDepthOptions' own fields.
    s["solver"] = Field(&O::solver);
    s["rasterizer"] = Field(&O::rasterizer);
    s["track_junctions"] = Field(&O::track_junctions);
    s["points_per_line"] = Field(&O::points_per_line);
    s["min_width"] = Field(&O::min_width);
    s["max_width"] = Field(&O::max_width);
    s["max_abs_yaw"] = Field(&O::max_abs_yaw);
    s["max_abs_pitch"] = Field(&O::max_abs_pitch);
    s["max_line_error"] = Field(&O::max_line_error);
    s["ceiling_height"] = Field(&O::ceiling_height);
    s["estimate_ceiling"] = Field(&O::estimate_ceiling);
    s["ceiling_checks_baseboards"] = Field(&O::ceiling_checks_baseboards);
    s["ceiling_checks_inner_lines"] = Field(&O::ceiling_checks_inner_lines);
    s["width_prior"] = Field(&O::width_prior);
    s["max_width_change"] = Field(&O::max_width_change);
    s["max_ceiling_disagreement"] = Field(&O::max_ceiling_disagreement);
    s["max_ceiling_change"] = Field(&O::max_ceiling_change);
    s["estimate_end_wall"] = Field(&O::estimate_end_wall);
    s["search_max_width"] = Field(&O::search_max_width);
    s["min_confidence"] = Field(&O::min_confidence);
    // The tools' flag names for the same or nested fields.
    s["end_wall"] = Field(&O::estimate_end_wall);
    s["inner_line_check"] = Field(&O::ceiling_checks_inner_lines);
    s["max_range"] = Nested(&O::rasterizer_options, &RasterizerOptions::max_range);
    s["max_height"] = Nested(&O::rasterizer_options, &RasterizerOptions::max_height);
    s["redetect_interval"] = Nested(&O::tracker, &JunctionTrackerOptions::redetect_interval);
    s["junction_max_width"] = Nested(&O::perception, &JunctionDetectorOptions::max_work_width);
    s["baseboard_band_contrast"] =
        Nested(&O::perception, &JunctionDetectorOptions::baseboard_band_contrast);
    s["roi_top"] = Nested(&O::perception, &JunctionDetectorOptions::roi_top_fraction);
    s["max_floor_texture"] = Nested(&O::perception, &JunctionDetectorOptions::max_floor_texture);
    s["hough_angle_window"] =
        Nested(&O::perception, &JunctionDetectorOptions::hough_angle_window_deg);
    s["relaxed_hough_threshold"] =
        Nested(&O::perception, &JunctionDetectorOptions::relaxed_hough_threshold);
    // The solvers' shared options.
    s["loss"] = Nested(&O::solver_options, &SolverOptions::loss);
    s["loss_scale"] = Nested(&O::solver_options, &SolverOptions::loss_scale);
    s["max_rounds"] = Nested(&O::solver_options, &SolverOptions::max_rounds);
    s["initial_pitch"] = Nested(&O::solver_options, &SolverOptions::initial_pitch);
    return s;
  }();
  return setters;
}

}  // namespace

RecoverDepthOptions OptionsFromKwargs(const py::kwargs& kwargs, py::object* camera_height) {
  RecoverDepthOptions options;
  *camera_height = py::none();
  for (const auto& item : kwargs) {
    const std::string name = py::cast<std::string>(item.first);
    if (name == "camera_height") {
      *camera_height = py::reinterpret_borrow<py::object>(item.second);
      continue;
    }
    const auto it = Setters().find(name);
    if (it == Setters().end()) {
      throw py::type_error("unexpected keyword argument '" + name + "'");
    }
    try {
      it->second(&options, item.second);
    } catch (const py::cast_error&) {
      throw py::type_error("keyword argument '" + name + "': wrong type " +
                           std::string(py::str(py::type::of(item.second))));
    }
  }
  return options;
}

std::vector<std::string> OptionNames() {
  std::vector<std::string> names;
  for (const auto& entry : Setters()) names.push_back(entry.first);
  return names;
}

}  // namespace python
}  // namespace corridor
