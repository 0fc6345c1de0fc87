#include "corridor_depth/truth_yaml.h"

#include <set>

#include <yaml-cpp/yaml.h>

#include "corridor_depth/image_io.h"
#include "io/yaml_util.h"

namespace corridor {
namespace {

// One entry of `frames:`. ceiling_height is optional (0 = no ceiling); the rest are required.
Status ReadFrame(const YAML::Node& node, const YamlContext& ctx, FrameTruth* truth) {
  if (!node.IsMap()) {
    return Status::InvalidArgument(ctx.path + ": '" + ctx.prefix + "' is not a map");
  }
  CorridorGeometry& g = truth->geometry;
  Status status = GetYamlString(node, "file", ctx, true, &truth->file);
  if (status.ok() && truth->file.empty()) {
    status = Status::InvalidArgument(ctx.path + ": key '" + ctx.Key("file") + "' is empty");
  }
  if (status.ok()) status = GetYamlDouble(node, "pitch", ctx, true, &g.pitch);
  if (status.ok()) status = GetYamlDouble(node, "yaw", ctx, true, &g.yaw);
  if (status.ok()) status = GetYamlDouble(node, "offset", ctx, true, &g.offset);
  if (status.ok()) status = GetYamlDouble(node, "width", ctx, true, &g.width);
  if (status.ok()) status = GetYamlDouble(node, "camera_height", ctx, true, &g.camera_height);
  if (status.ok()) status = GetYamlDouble(node, "ceiling_height", ctx, false, &g.ceiling_height);
  return status;
}

}  // namespace

Status ReadTruthYaml(const std::string& path, std::vector<FrameTruth>* frames) {
  YAML::Node root;
  Status status = LoadYamlMap(path, &root);
  if (!status.ok()) return status;
  const YAML::Node list = root["frames"];
  if (!list.IsDefined()) return Status::InvalidArgument(path + ": missing key 'frames'");
  if (list.IsNull()) {  // "frames:" with nothing under it.
    frames->clear();
    return Status::Ok();
  }
  if (!list.IsSequence()) return Status::InvalidArgument(path + ": key 'frames' is not a list");
  std::vector<FrameTruth> result(list.size());
  std::set<std::string> seen;
  for (size_t i = 0; i < list.size(); ++i) {
    const YamlContext ctx{path, "frames[" + std::to_string(i) + "]"};
    try {
      status = ReadFrame(list[i], ctx, &result[i]);
    } catch (const YAML::Exception& e) {  // Defensive: yaml-cpp throws on odd node shapes.
      status = Status::InvalidArgument(path + ": unexpected YAML structure in " + ctx.prefix +
                                       ": " + e.msg);
    }
    if (!status.ok()) return status;
    if (!seen.insert(result[i].file).second) {
      return Status::InvalidArgument(path + ": file '" + result[i].file + "' is listed twice");
    }
  }
  *frames = std::move(result);
  return Status::Ok();
}

Status WriteTruthYaml(const std::string& path, const std::vector<FrameTruth>& frames) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);  // Round-trips every double exactly.
  out << YAML::BeginMap << YAML::Key << "frames" << YAML::Value << YAML::BeginSeq;
  for (const FrameTruth& f : frames) {
    const CorridorGeometry& g = f.geometry;
    out << YAML::BeginMap;
    out << YAML::Key << "file" << YAML::Value << f.file;
    out << YAML::Key << "pitch" << YAML::Value << g.pitch;
    out << YAML::Key << "yaw" << YAML::Value << g.yaw;
    out << YAML::Key << "offset" << YAML::Value << g.offset;
    out << YAML::Key << "width" << YAML::Value << g.width;
    out << YAML::Key << "camera_height" << YAML::Value << g.camera_height;
    out << YAML::Key << "ceiling_height" << YAML::Value << g.ceiling_height;
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  if (!out.good()) return Status::Internal(path + ": YAML emitter failed: " + out.GetLastError());
  return WriteTextAtomic(path, std::string(out.c_str()) + "\n");
}

}  // namespace corridor
