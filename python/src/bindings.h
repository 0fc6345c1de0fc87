#pragma once

// One function per binding file; module.cc calls them in order (types before their users).

#include <pybind11/pybind11.h>

namespace corridor {
namespace python {

void BindCamera(pybind11::module_& m);     // camera.cc: Camera, read_image, write_depth_png
void BindRecover(pybind11::module_& m);    // recover.cc: Status, Geometry, Junctions, Result, recover_depth
void BindSequence(pybind11::module_& m);   // sequence.cc: Sequence
void BindSolvers(pybind11::module_& m);    // solvers.cc: SolverSummary, solve
void BindResiduals(pybind11::module_& m);  // residuals.cc: symmetry_residual, width_residual
void BindMetrics(pybind11::module_& m);    // metrics.cc: DepthMetrics, depth_metrics

}  // namespace python
}  // namespace corridor
