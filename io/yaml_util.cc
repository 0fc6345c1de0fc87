#include "io/yaml_util.h"

#include "io/file_util.h"

namespace corridor {
namespace {

Status Missing(const YamlContext& ctx, const std::string& key) {
  return Status::InvalidArgument(ctx.path + ": missing key '" + ctx.Key(key) + "'");
}

// The node's text for messages: the scalar itself, or its kind.
std::string Describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "empty";
}

// Looks up map[key]: *node is set when present. Fails only when `required` and absent.
Status Find(const YAML::Node& map, const std::string& key, const YamlContext& ctx, bool required,
            YAML::Node* node, bool* present) {
  *present = false;
  if (!map.IsMap()) {
    const std::string where = ctx.prefix.empty() ? "the top level" : "'" + ctx.prefix + "'";
    return Status::InvalidArgument(ctx.path + ": " + where + " is not a map");
  }
  const YAML::Node found = map[key];
  if (!found.IsDefined() || found.IsNull()) return required ? Missing(ctx, key) : Status::Ok();
  *node = found;
  *present = true;
  return Status::Ok();
}

}  // namespace

std::string YamlContext::Key(const std::string& key) const {
  return prefix.empty() ? key : prefix + "." + key;
}

Status LoadYamlMap(const std::string& path, YAML::Node* root) {
  std::string text;
  const Status status = ReadFileToString(path, &text);
  if (!status.ok()) return status;
  return ParseYamlMap(text, path, root);
}

Status ParseYamlMap(const std::string& text, const std::string& path, YAML::Node* root) {
  try {
    *root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    return Status::InvalidArgument(path + ": YAML syntax error at line " +
                                   std::to_string(e.mark.line + 1) + ", column " +
                                   std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
  if (root->IsNull()) return Status::InvalidArgument(path + ": file is empty");
  if (!root->IsMap()) return Status::InvalidArgument(path + ": top level is not a YAML map");
  return Status::Ok();
}

Status YamlToDouble(const YAML::Node& node, const std::string& what, const YamlContext& ctx,
                    double* value) {
  try {
    if (node.IsScalar()) {
      *value = node.as<double>();
      return Status::Ok();
    }
  } catch (const YAML::Exception&) {
  }
  return Status::InvalidArgument(ctx.path + ": key '" + what + "' is not a number: " +
                                 Describe(node));
}

Status GetYamlDouble(const YAML::Node& map, const std::string& key, const YamlContext& ctx,
                     bool required, double* value) {
  YAML::Node node;
  bool present = false;
  Status status = Find(map, key, ctx, required, &node, &present);
  if (!status.ok() || !present) return status;
  return YamlToDouble(node, ctx.Key(key), ctx, value);
}

Status GetYamlInt(const YAML::Node& map, const std::string& key, const YamlContext& ctx,
                  bool required, int* value) {
  YAML::Node node;
  bool present = false;
  Status status = Find(map, key, ctx, required, &node, &present);
  if (!status.ok() || !present) return status;
  try {
    if (node.IsScalar()) {
      *value = node.as<int>();
      return Status::Ok();
    }
  } catch (const YAML::Exception&) {
  }
  return Status::InvalidArgument(ctx.path + ": key '" + ctx.Key(key) + "' is not an integer: " +
                                 Describe(node));
}

Status GetYamlString(const YAML::Node& map, const std::string& key, const YamlContext& ctx,
                     bool required, std::string* value) {
  YAML::Node node;
  bool present = false;
  Status status = Find(map, key, ctx, required, &node, &present);
  if (!status.ok() || !present) return status;
  if (!node.IsScalar()) {
    return Status::InvalidArgument(ctx.path + ": key '" + ctx.Key(key) + "' is not a string: " +
                                   Describe(node));
  }
  *value = node.Scalar();
  return Status::Ok();
}

}  // namespace corridor
