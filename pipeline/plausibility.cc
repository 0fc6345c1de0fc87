#include "pipeline/plausibility.h"

#include <cmath>
#include <sstream>

#include "estimation/line_fit.h"

namespace corridor {

Status CheckPlausible(const CorridorGeometry& g, const RecoverDepthOptions& options) {
  const Status shape = CheckPlausibleShape(g, options);
  return shape.ok() ? CheckCorridorWidth(g, options) : shape;
}

Status CheckCorridorWidth(const CorridorGeometry& g, const RecoverDepthOptions& options) {
  std::ostringstream msg;
  if (g.width < options.min_width) {
    msg << "width " << g.width << " m is narrower than min_corridor_width " << options.min_width
        << " m";
  } else if (g.width > options.max_width) {
    msg << "width " << g.width << " m is wider than max_corridor_width " << options.max_width
        << " m: a line on a wall (a rail, a wainscot's top) taken for the floor's edge, or a "
           "hall rather than a corridor";
  } else {
    return Status::Ok();
  }
  return Status::ImplausibleGeometry(msg.str());
}

Status CheckPlausibleShape(const CorridorGeometry& g, const RecoverDepthOptions& options) {
  std::ostringstream msg;
  if (!std::isfinite(g.yaw) || !std::isfinite(g.pitch) || !std::isfinite(g.offset) ||
      !std::isfinite(g.width)) {
    msg << "non-finite estimate";
  } else if (!(g.width > 0)) {
    msg << "width " << g.width << " m is not positive";
  } else if (std::abs(g.yaw) > options.max_abs_yaw) {
    msg << "yaw " << g.yaw << " rad is beyond +-" << options.max_abs_yaw << " rad";
  } else if (std::abs(g.pitch) > options.max_abs_pitch) {
    msg << "pitch " << g.pitch << " rad is beyond +-" << options.max_abs_pitch << " rad";
  } else if (g.LeftDistance() <= 0 || g.RightDistance() <= 0) {
    msg << "the camera is not between the walls (offset " << g.offset << " m, width " << g.width
        << " m)";
  } else {
    return Status::Ok();
  }
  return Status::ImplausibleGeometry(msg.str());
}

Status CheckLineFit(const CorridorGeometry& g, const CorridorObservation& observation,
                    const Camera& camera, const RecoverDepthOptions& options) {
  double rms = 0;
  const bool defined = JunctionLineRms(g, observation, &rms);
  const double limit = options.max_line_error * std::hypot(camera.image_width, camera.image_height);
  if (defined && rms <= limit) return Status::Ok();
  std::ostringstream msg;
  msg << "the estimate does not explain the junction lines (points " << rms
      << " px RMS from the predicted lines, limit " << limit << " px)";
  return Status::ImplausibleGeometry(msg.str());
}

}  // namespace corridor
