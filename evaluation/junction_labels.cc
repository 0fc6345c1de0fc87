#include "evaluation/junction_labels.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include <Eigen/Geometry>

#include "corridor_depth/corridor_frame.h"
#include "io/csv_row.h"

namespace corridor {
namespace {

// The columns junctions.csv must have, in any order.
const char* const kColumns[] = {"file", "width", "height", "lx1", "ly1", "lx2", "ly2", "rx1",
                                "ry1", "rx2", "ry2", "kind", "quality", "fx", "fy", "cx",
                                "cy"};

bool ParseNumber(const std::string& text, double* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end != nullptr && *end == '\0' && std::isfinite(*value);
}

}  // namespace

const char* LabelVerdictName(LabelVerdict verdict) {
  switch (verdict) {
    case LabelVerdict::kRight:
      return "right";
    case LabelVerdict::kRough:
      return "rough";
    case LabelVerdict::kOkButWrong:
      return "ok but wrong";
    case LabelVerdict::kRefused:
      break;
  }
  return "refused";
}

Status ReadJunctionLabels(const std::string& path, std::vector<JunctionLabel>* labels) {
  labels->clear();
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::NotFound(path + ": cannot open the junction labels");
  std::string line;
  std::vector<std::string> header, fields;
  std::map<std::string, size_t> column;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::string where = path + ": line " + std::to_string(number);
    if (header.empty()) {
      SplitCsvRow(line, &header);
      for (size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
      for (const char* name : kColumns) {
        if (column.count(name) == 0) {
          return Status::InvalidArgument(where + ": the header has no column '" + name + "'");
        }
      }
      continue;
    }
    if (!SplitCsvRow(line, &fields) || fields.size() != header.size()) {
      return Status::InvalidArgument(where + ": expected " + std::to_string(header.size()) +
                                     " fields");
    }
    const auto field = [&](const char* name) -> const std::string& { return fields[column[name]]; };
    JunctionLabel label;
    label.file = field("file");
    label.kind = field("kind");
    label.quality = field("quality");
    double w = 0, h = 0;
    if (label.file.empty() || !ParseNumber(field("width"), &w) || !ParseNumber(field("height"), &h) ||
        !(w > 0 && h > 0)) {
      return Status::InvalidArgument(where +
                                     ": a file name and a positive width and height are "
                                     "required");
    }
    label.width = static_cast<int>(w);
    label.height = static_cast<int>(h);
    const char* const names[2][4] = {{"lx1", "ly1", "lx2", "ly2"}, {"rx1", "ry1", "rx2", "ry2"}};
    for (int s = 0; s < 2; ++s) {
      double v[4];
      int present = 0;
      for (int k = 0; k < 4; ++k) present += ParseNumber(field(names[s][k]), &v[k]);
      if (present != 0 && present != 4) {
        return Status::InvalidArgument(where + ": side " + (s == 0 ? "left" : "right") +
                                       " needs all four coordinates or none");
      }
      label.has_side[s] = present == 4;
      if (label.has_side[s]) label.side[s] = {Eigen::Vector2d(v[0], v[1]), Eigen::Vector2d(v[2], v[3])};
    }
    label.has_camera = ParseNumber(field("fx"), &label.fx) && ParseNumber(field("fy"), &label.fy) &&
                       ParseNumber(field("cx"), &label.cx) && ParseNumber(field("cy"), &label.cy);
    labels->push_back(label);
  }
  if (header.empty()) return Status::InvalidArgument(path + ": empty");
  return Status::Ok();
}

bool ProjectedJunction(const CorridorGeometry& g, const Camera& camera, int side,
                       Eigen::Vector3d* line, double roll) {
  const double x = side == 0 ? -g.LeftDistance() : g.RightDistance();
  if (!(g.width > 0) || !std::isfinite(x)) return false;
  const CorridorRotation<double> r(g.pitch, g.yaw);
  // Two points of the 3D line in front of the camera, as homogeneous ideal pixels.
  Eigen::Vector3d p[2];
  const double along[2] = {3.0, 60.0};
  for (int k = 0; k < 2; ++k) {
    const Vec3<double> c =
        TurnedByRoll(r.ToCamera({x, g.camera_height, along[k] * std::max(1.0, g.width)}), roll);
    if (!(c.z > 1e-6)) return false;
    p[k] = Eigen::Vector3d(camera.fx * c.x / c.z + camera.cx, camera.fy * c.y / c.z + camera.cy, 1);
  }
  Eigen::Vector3d l = p[0].cross(p[1]);
  const double norm = l.head<2>().norm();
  if (!(norm > 0) || !l.allFinite()) return false;
  *line = l / norm;
  return true;
}

LabelScore ScoreAgainstLabel(const JunctionLabel& label, bool ok, const CorridorGeometry& geometry,
                             const Camera& camera, double roll) {
  LabelScore score;
  if (!ok) return score;
  double worst = 0;
  for (int s = 0; s < 2; ++s) {
    if (!label.has_side[s]) continue;
    Eigen::Vector3d line;
    double error = 1.0;
    if (ProjectedJunction(geometry, camera, s, &line, roll)) {
      error = 0;
      for (const Eigen::Vector2d& raw : label.side[s]) {
        const Eigen::Vector2d p = camera.Undistort(raw);
        error = std::max(error, std::abs(line.dot(p.homogeneous())) / label.height);
      }
    }
    score.side_error[s] = error;
    worst = std::max(worst, error);
  }
  score.verdict = worst <= 0.02  ? LabelVerdict::kRight
                  : worst > 0.05 ? LabelVerdict::kOkButWrong
                                 : LabelVerdict::kRough;
  return score;
}

}  // namespace corridor
