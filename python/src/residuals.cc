// symmetry_residual and width_residual: the two cost functors of the solvers at given parameters.

#include "corridor_depth/residual_loss.h"
#include "corridor_depth/symmetry_residual.h"
#include "corridor_depth/width_residual.h"
#include "python/src/bindings.h"
#include "python/src/common.h"

namespace corridor {
namespace python {
namespace {

struct FunctorInput {
  FloorIntrinsics intrinsics;
  ResidualLoss loss;
  std::vector<Eigen::Vector2d> left, right;
};

FunctorInput Input(const py::handle& left, const py::handle& right, const Camera& camera,
                   const py::object& camera_height, const std::string& loss, double loss_scale) {
  const Camera with_height = WithHeight(camera, camera_height);
  FunctorInput in;
  in.intrinsics = {with_height.fx, with_height.fy, with_height.cx, with_height.cy,
                   with_height.mount_height};
  if (!ResidualLoss::FromName(loss, loss_scale, &in.loss)) {
    throw py::value_error("loss must be none, huber or cauchy, not '" + loss + "'");
  }
  in.left = Undistorted(PointsFromArray(left, "left_points"), with_height);
  in.right = Undistorted(PointsFromArray(right, "right_points"), with_height);
  if (in.left.size() < 2 || in.right.size() < 2) {
    throw py::value_error("each side needs at least 2 points");
  }
  return in;
}

template <typename Functor>
py::array_t<double> Evaluate(const Functor& functor, const double* x) {
  py::array_t<double> out(functor.NumResiduals());
  if (!functor(x, out.mutable_data())) {
    throw py::value_error(
        "the residuals are undefined here: a point does not map to the floor in front of the "
        "camera, or a side's points are degenerate");
  }
  return out;
}

}  // namespace

void BindResiduals(py::module_& m) {
  m.def(
      "symmetry_residual",
      [](const py::handle& left, const py::handle& right, const Camera& camera, double yaw,
         double offset, double pitch, const py::object& camera_height, const std::string& loss,
         double loss_scale) {
        FunctorInput in = Input(left, right, camera, camera_height, loss, loss_scale);
        const SymmetryResidual functor(in.intrinsics, pitch, std::move(in.left),
                                       std::move(in.right), in.loss);
        const double x[2] = {yaw, offset};
        return Evaluate(functor, x);
      },
      py::arg("left_points"), py::arg("right_points"), py::arg("camera"), py::kw_only(),
      py::arg("yaw"), py::arg("offset"), py::arg("pitch"), py::arg("camera_height") = py::none(),
      py::arg("loss") = "none", py::arg("loss_scale") = 2.0,
      "Stage 1's residuals (paper III-B): for each left then right point (raw pixels), the "
      "horizontal pixel distance in the virtual image between the mirrored point and the "
      "opposite line, at (yaw, offset) with the pitch held.");
  m.def(
      "width_residual",
      [](const py::handle& left, const py::handle& right, const Camera& camera, double pitch,
         double width, double yaw, double offset, const py::object& camera_height,
         const std::string& loss, double loss_scale) {
        FunctorInput in = Input(left, right, camera, camera_height, loss, loss_scale);
        const WidthResidual functor(in.intrinsics, yaw, offset, std::move(in.left),
                                    std::move(in.right), in.loss);
        const double x[2] = {pitch, width};
        return Evaluate(functor, x);
      },
      py::arg("left_points"), py::arg("right_points"), py::arg("camera"), py::kw_only(),
      py::arg("pitch"), py::arg("width"), py::arg("yaw"), py::arg("offset"),
      py::arg("camera_height") = py::none(), py::arg("loss") = "none",
      py::arg("loss_scale") = 2.0,
      "Stage 2's residuals (paper III-C): for each left then right point (raw pixels), its "
      "distance from its wall on the floor, in pixels (fx / z), at (pitch, width) with the yaw "
      "and offset held.");
}

}  // namespace python
}  // namespace corridor
