#include "ros/geometry_message.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace corridor {
namespace {

std::string Number(double value) {
  if (!std::isfinite(value)) return "nan";
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", value);
  return text;
}

diagnostic_msgs::KeyValue Pair(const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue pair;
  pair.key = key;
  pair.value = value;
  return pair;
}

}  // namespace

diagnostic_msgs::DiagnosticStatus GeometryMessage(const std::string& stamp,
                                                  const std::string& frame_id,
                                                  const Status& status,
                                                  const RecoverDepthResult* result,
                                                  const Camera* camera) {
  diagnostic_msgs::DiagnosticStatus message;
  const std::string status_class = StatusClass(status.code());
  message.level = status_class == "ok"        ? diagnostic_msgs::DiagnosticStatus::OK
                  : status_class == "refused" ? diagnostic_msgs::DiagnosticStatus::WARN
                                              : diagnostic_msgs::DiagnosticStatus::ERROR;
  message.name = "corridor_depth/geometry";
  message.message = status.ok() ? "ok" : status.message();
  message.hardware_id = frame_id;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool has = result != nullptr && result->has_geometry && status.ok();
  const CorridorGeometry g = has ? result->geometry : CorridorGeometry();
  const auto value = [&](double v) { return Number(has ? v : nan); };
  auto& values = message.values;
  values.push_back(Pair("stamp", stamp));
  values.push_back(Pair("status", status_class));
  const std::string note = status.ok() ? (result ? result->fallback : "")
                                       : std::string(StatusCodeName(status.code())) + ": " +
                                             status.message();
  values.push_back(Pair("note", note));
  values.push_back(Pair("confidence", Number(result ? result->confidence : nan)));
  values.push_back(Pair("yaw_rad", value(g.yaw)));
  values.push_back(Pair("pitch_rad", value(g.pitch)));
  values.push_back(Pair("roll_rad", value(has ? result->roll : 0.0)));
  values.push_back(Pair("offset_m", value(g.offset)));
  values.push_back(Pair("width_m", value(g.width)));
  values.push_back(Pair("ceiling_height_m", value(g.HasCeiling() ? g.ceiling_height : 0.0)));
  values.push_back(Pair("end_distance_m", value(g.end_distance)));
  values.push_back(Pair("camera_height_m", value(g.camera_height)));
  values.push_back(Pair("fx_px", Number(camera ? camera->fx : nan)));
  values.push_back(Pair("fy_px", Number(camera ? camera->fy : nan)));
  values.push_back(Pair("cx_px", Number(camera ? camera->cx : nan)));
  values.push_back(Pair("cy_px", Number(camera ? camera->cy : nan)));
  values.push_back(Pair("time_s", Number(result ? result->times.total : nan)));
  return message;
}

}  // namespace corridor
