#pragma once

// What recover_depth and Sequence.process return: the outputs of a RecoverDepthResult as Python
// sees them (no working images).

#include <string>

#include <pybind11/numpy.h>

#include "corridor_depth/recover_depth.h"

namespace corridor {
namespace python {

struct PyResult {
  Status status;
  bool has_geometry = false;
  CorridorGeometry geometry;
  JunctionPair junctions;
  SolverSummary solver_summary;
  bool ceiling_found = false;
  bool end_wall_found = false;
  std::string fallback;
  bool width_held = false, walls_scaled = false, ceiling_held = false;
  bool junctions_tracked = false, ceiling_trusted = false;
  double confidence = 0;
  double roll = 0;
  StageTimes times;
  pybind11::array_t<float> depth;  // float32 HxW metres, NaN = no estimate.
};

// The Python result of a frame of rows x cols pixels (with the GIL held). Raises for a caller's
// error (ValueError with the status message, ...); a refused or failed frame is returned.
PyResult MakeResult(RecoverDepthResult&& result, int rows, int cols);

}  // namespace python
}  // namespace corridor
