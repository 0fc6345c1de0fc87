#include "python/src/result.h"

#include "python/src/common.h"

namespace corridor {
namespace python {

PyResult MakeResult(RecoverDepthResult&& result, int rows, int cols) {
  if (IsCallerError(result.status)) ThrowStatus(result.status);
  PyResult out;
  out.status = result.status;
  out.has_geometry = result.has_geometry;
  out.geometry = result.geometry;
  out.junctions = std::move(result.junctions);
  out.junctions.segments.clear();
  out.solver_summary = result.solver_summary;
  out.ceiling_found = result.ceiling.found;
  out.end_wall_found = result.end_wall.found;
  out.fallback = result.fallback;
  out.width_held = result.width_held;
  out.walls_scaled = result.walls_scaled;
  out.ceiling_held = result.ceiling_held;
  out.junctions_tracked = result.junctions_tracked;
  out.ceiling_trusted = result.ceiling_trusted;
  out.confidence = result.confidence;
  out.roll = result.roll;
  out.times = result.times;
  out.depth = DepthToArray(std::move(result.depth), rows, cols);
  return out;
}

}  // namespace python
}  // namespace corridor
