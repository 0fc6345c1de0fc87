#pragma once

// Private helpers of corridor_io for reading YAML files with errors that name the file and the
// key. Not installed.

#include <string>

#include <yaml-cpp/yaml.h>

#include "corridor_depth/status.h"

namespace corridor {

// Loads a YAML file whose top level must be a map. Errors name the file; syntax errors carry
// yaml-cpp's line and column (1-based).
Status LoadYamlMap(const std::string& path, YAML::Node* root);
// The same for YAML text already in memory; `path` only names it in messages.
Status ParseYamlMap(const std::string& text, const std::string& path, YAML::Node* root);

// Where a value comes from, for messages: "<file>: key 'camera_matrix.data[2]' ...".
struct YamlContext {
  std::string path;    // The YAML file.
  std::string prefix;  // Key path of the enclosing map, e.g. "frames[3]"; empty at the top.

  // "<prefix>.<key>", or just key at the top level.
  std::string Key(const std::string& key) const;
};

// Reads map[key] as a number (NaN/inf are accepted here; callers validate ranges). When the key
// is absent: an error if `required`, else *value is left untouched.
Status GetYamlDouble(const YAML::Node& map, const std::string& key, const YamlContext& ctx,
                     bool required, double* value);
// Same for integers ("640"; "640.5" is an error).
Status GetYamlInt(const YAML::Node& map, const std::string& key, const YamlContext& ctx,
                  bool required, int* value);
// Same for scalars read as strings.
Status GetYamlString(const YAML::Node& map, const std::string& key, const YamlContext& ctx,
                     bool required, std::string* value);

// Converts a scalar node to a number; `what` names it in the error ("camera_matrix.data[4]").
Status YamlToDouble(const YAML::Node& node, const std::string& what, const YamlContext& ctx,
                    double* value);

}  // namespace corridor
