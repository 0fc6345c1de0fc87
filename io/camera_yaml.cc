#include "corridor_depth/camera_yaml.h"

#include <array>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "corridor_depth/image_io.h"
#include "io/yaml_util.h"

namespace corridor {
namespace {

// Reads `key: {rows, cols, data: [...]}` into *data. rows/cols are optional; when present their
// product must match the length of data. At most `max_size` values are accepted.
Status ReadMatrix(const YAML::Node& root, const std::string& key, const YamlContext& ctx,
                  size_t max_size, std::vector<double>* data) {
  const YAML::Node m = root[key];
  if (!m.IsMap()) return Status::InvalidArgument(ctx.path + ": key '" + key + "' is not a map");
  const YAML::Node list = m["data"];
  if (!list.IsDefined() || list.IsNull()) {
    return Status::InvalidArgument(ctx.path + ": missing key '" + key + ".data'");
  }
  if (!list.IsSequence()) {
    return Status::InvalidArgument(ctx.path + ": key '" + key + ".data' is not a list");
  }
  if (list.size() > max_size) {
    return Status::InvalidArgument(ctx.path + ": key '" + key + ".data' has " +
                                   std::to_string(list.size()) + " values, at most " +
                                   std::to_string(max_size) + " are supported");
  }
  const YamlContext sub{ctx.path, key};
  int rows = -1, cols = -1;
  Status status = GetYamlInt(m, "rows", sub, false, &rows);
  if (status.ok()) status = GetYamlInt(m, "cols", sub, false, &cols);
  if (!status.ok()) return status;
  if (rows >= 0 && cols >= 0 && static_cast<size_t>(rows) * cols != list.size()) {
    return Status::InvalidArgument(ctx.path + ": key '" + key + "' is " + std::to_string(rows) +
                                   "x" + std::to_string(cols) + " but its data has " +
                                   std::to_string(list.size()) + " values");
  }
  data->assign(list.size(), 0.0);
  for (size_t i = 0; i < list.size(); ++i) {
    status = YamlToDouble(list[i], key + ".data[" + std::to_string(i) + "]", ctx, &(*data)[i]);
    if (!status.ok()) return status;
  }
  return Status::Ok();
}

Status ReadIntrinsics(const YAML::Node& root, const YamlContext& ctx, Camera* camera) {
  if (!root["camera_matrix"].IsDefined()) {
    return Status::InvalidArgument(ctx.path + ": missing key 'camera_matrix'");
  }
  std::vector<double> k;
  Status status = ReadMatrix(root, "camera_matrix", ctx, 9, &k);
  if (!status.ok()) return status;
  if (k.size() != 9) {
    return Status::InvalidArgument(ctx.path + ": key 'camera_matrix.data' must have 9 values, has " +
                                   std::to_string(k.size()));
  }
  // K = [fx s cx; 0 fy cy; 0 0 1]. The Camera model has no skew.
  if (k[1] != 0 || k[3] != 0 || k[6] != 0 || k[7] != 0 || k[8] != 1) {
    return Status::InvalidArgument(ctx.path +
                                   ": key 'camera_matrix' must be [fx 0 cx; 0 fy cy; "
                                   "0 0 1] (no skew)");
  }
  camera->fx = k[0];
  camera->cx = k[2];
  camera->fy = k[4];
  camera->cy = k[5];
  return Status::Ok();
}

Status ReadDistortion(const YAML::Node& root, const YamlContext& ctx, Camera* camera) {
  camera->distortion.fill(0.0);
  std::string model = "plumb_bob";
  Status status = GetYamlString(root, "distortion_model", ctx, false, &model);
  if (!status.ok()) return status;
  if (model == "none") return Status::Ok();
  if (model != "plumb_bob") {
    return Status::InvalidArgument(ctx.path + ": distortion_model '" + model +
                                   "' is not supported (use plumb_bob or none)");
  }
  const YAML::Node node = root["distortion_coefficients"];
  if (!node.IsDefined() || node.IsNull()) return Status::Ok();  // Absent: rectified.
  std::vector<double> d;
  status = ReadMatrix(root, "distortion_coefficients", ctx, camera->distortion.size(), &d);
  if (!status.ok()) return status;
  for (size_t i = 0; i < d.size(); ++i) camera->distortion[i] = d[i];  // Fewer: zero-padded.
  return Status::Ok();
}

// Emits `key: {rows, cols, data: [...]}` in ROS's layout.
void EmitMatrix(YAML::Emitter* out, const std::string& key, int rows, int cols,
                const std::vector<double>& data) {
  *out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  *out << YAML::Key << "rows" << YAML::Value << rows;
  *out << YAML::Key << "cols" << YAML::Value << cols;
  *out << YAML::Key << "data" << YAML::Value << YAML::Flow << data;
  *out << YAML::EndMap;
}

// Reads the camera from a loaded YAML map; messages name `path`.
Status CameraFromYaml(const YAML::Node& root, const std::string& path, Camera* camera) {
  const YamlContext ctx{path, ""};
  Status status;
  Camera c;
  try {
    status = GetYamlInt(root, "image_width", ctx, true, &c.image_width);
    if (status.ok()) status = GetYamlInt(root, "image_height", ctx, true, &c.image_height);
    if (status.ok()) status = ReadIntrinsics(root, ctx, &c);
    if (status.ok()) status = ReadDistortion(root, ctx, &c);
    if (status.ok()) status = GetYamlDouble(root, "camera_height", ctx, false, &c.mount_height);
  } catch (const YAML::Exception& e) {  // Defensive: yaml-cpp throws on odd node shapes.
    status = Status::InvalidArgument(path + ": unexpected YAML structure: " + e.msg);
  }
  if (!status.ok()) return status;
  std::string why;
  if (!c.CheckIntrinsics(&why)) return Status::InvalidArgument(path + ": " + why);
  *camera = c;
  return Status::Ok();
}

}  // namespace

Status ReadCameraYaml(const std::string& path, Camera* camera) {
  YAML::Node root;
  const Status status = LoadYamlMap(path, &root);
  if (!status.ok()) return status;
  return CameraFromYaml(root, path, camera);
}

Status ParseCameraYaml(const std::string& text, const std::string& name, Camera* camera) {
  YAML::Node root;
  const Status status = ParseYamlMap(text, name, &root);
  if (!status.ok()) return status;
  return CameraFromYaml(root, name, camera);
}

Status WriteCameraYaml(const std::string& path, const Camera& camera) {
  std::string why;
  if (!camera.CheckIntrinsics(&why)) {
    return Status::InvalidArgument(path + ": refusing to write an invalid camera: " + why);
  }
  const double fx = camera.fx, fy = camera.fy, cx = camera.cx, cy = camera.cy;
  YAML::Emitter out;
  out.SetDoublePrecision(17);  // Round-trips every double exactly.
  out << YAML::BeginMap;
  out << YAML::Key << "image_width" << YAML::Value << camera.image_width;
  out << YAML::Key << "image_height" << YAML::Value << camera.image_height;
  out << YAML::Key << "camera_name" << YAML::Value << "camera";
  EmitMatrix(&out, "camera_matrix", 3, 3, {fx, 0, cx, 0, fy, cy, 0, 0, 1});
  out << YAML::Key << "distortion_model" << YAML::Value << "plumb_bob";
  EmitMatrix(&out, "distortion_coefficients", 1, 5,
             std::vector<double>(camera.distortion.begin(), camera.distortion.end()));
  EmitMatrix(&out, "rectification_matrix", 3, 3, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  EmitMatrix(&out, "projection_matrix", 3, 4, {fx, 0, cx, 0, 0, fy, cy, 0, 0, 0, 1, 0});
  out << YAML::Key << "camera_height" << YAML::Value << camera.mount_height;
  out << YAML::EndMap;
  if (!out.good()) return Status::Internal(path + ": YAML emitter failed: " + out.GetLastError());
  return WriteTextAtomic(path, std::string(out.c_str()) + "\n");
}

}  // namespace corridor
