// SolverSummary and solve: the solvers by name on junction points.

#include "corridor_depth/corridor_observation.h"
#include "corridor_depth/solver.h"
#include "python/src/bindings.h"
#include "python/src/common.h"

namespace corridor {
namespace python {
namespace {

SolverOptions SolverOptionsFromKwargs(const py::kwargs& kwargs) {
  SolverOptions options;
  for (const auto& item : kwargs) {
    const std::string name = py::cast<std::string>(item.first);
    try {
      if (name == "loss") {
        options.loss = py::cast<std::string>(item.second);
      } else if (name == "loss_scale") {
        options.loss_scale = py::cast<double>(item.second);
      } else if (name == "max_rounds") {
        options.max_rounds = py::cast<int>(item.second);
      } else if (name == "round_tolerance") {
        options.round_tolerance = py::cast<double>(item.second);
      } else if (name == "initial_pitch") {
        options.initial_pitch = py::cast<double>(item.second);
      } else {
        throw py::type_error("unexpected keyword argument '" + name + "'");
      }
    } catch (const py::cast_error&) {
      throw py::type_error("keyword argument '" + name + "': wrong type " +
                           std::string(py::str(py::type::of(item.second))));
    }
  }
  return options;
}

py::tuple Solve(const std::string& name, const py::handle& left, const py::handle& right,
                const Camera& camera, const py::object& camera_height,
                const CorridorGeometry* initial, const py::kwargs& kwargs) {
  const SolverOptions options = SolverOptionsFromKwargs(kwargs);
  const Camera with_height = WithHeight(camera, camera_height);
  CorridorObservation observation = CorridorObservation::FromCamera(with_height);
  observation.left = Undistorted(PointsFromArray(left, "left_points"), with_height);
  observation.right = Undistorted(PointsFromArray(right, "right_points"), with_height);
  std::string why;
  if (!observation.Check(&why)) throw py::value_error(why);
  std::unique_ptr<CorridorSolver> solver;
  ThrowIfError(CreateSolver(name, options, &solver));
  SolverSummary summary;
  Status status;
  {
    py::gil_scoped_release release;
    status = solver->Solve(observation, initial, &summary);
  }
  ThrowIfError(status);
  return py::make_tuple(summary.estimate, summary);
}

}  // namespace

void BindSolvers(py::module_& m) {
  py::class_<SolverSummary>(m, "SolverSummary", "What a solver reported.")
      .def_readonly("estimate", &SolverSummary::estimate)
      .def_readonly("final_cost", &SolverSummary::final_cost)
      .def_readonly("evaluations", &SolverSummary::evaluations)
      .def_readonly("iterations", &SolverSummary::iterations)
      .def_readonly("seconds", &SolverSummary::seconds)
      .def_readonly("converged", &SolverSummary::converged)
      .def_readonly("solver_name", &SolverSummary::solver_name);

  m.def("solve", &Solve, py::arg("name"), py::arg("left_points"), py::arg("right_points"),
        py::arg("camera"), py::arg("camera_height") = py::none(), py::kw_only(),
        py::arg("initial") = nullptr,
        "Fits the corridor model to points on the two floor/wall junctions (N x 2 raw pixels, "
        "undistorted through the camera) with the solver `name` (grid, closed_form, lm, joint, "
        "or a chain such as closed_form+lm). Returns (Geometry, SolverSummary). Keywords: "
        "initial (a Geometry to start from), loss, loss_scale, max_rounds, round_tolerance, "
        "initial_pitch. ValueError on bad points, an unknown solver or a bad option.");
}

}  // namespace python
}  // namespace corridor
