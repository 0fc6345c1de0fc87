#include "corridor_depth/rasterizer.h"

#include <cmath>

#include "depth/exact_rasterizer.h"
#include "depth/no_estimate.h"
#include "depth/paper_rasterizer.h"

namespace corridor {

const char* RasterizerTypeToString(RasterizerType type) {
  switch (type) {
    case RasterizerType::kPaper:
      return "paper";
    case RasterizerType::kExact:
      return "exact";
  }
  return "unknown";
}

bool StringToRasterizerType(const std::string& name, RasterizerType* type) {
  for (RasterizerType t : {RasterizerType::kPaper, RasterizerType::kExact}) {
    if (name == RasterizerTypeToString(t)) {
      *type = t;
      return true;
    }
  }
  return false;
}

std::string ValidRasterizerNames() { return "paper, exact"; }

bool RasterizerOptions::Check(std::string* why) const {
  std::string reason;
  if (!(max_range > 0 && std::isfinite(max_range))) {
    reason = "max_range must be positive and finite";
  } else if (!(max_height > 0 && std::isfinite(max_height))) {
    reason = "max_height must be positive and finite";
  } else if (paper_planes < 2 || paper_planes > 100000) {
    reason = "paper_planes must be in [2, 100000]";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

std::unique_ptr<DepthRasterizer> CreateRasterizer(RasterizerType type,
                                                  const RasterizerOptions& options) {
  switch (type) {
    case RasterizerType::kPaper:
      return std::make_unique<PaperRasterizer>(options);
    case RasterizerType::kExact:
      return std::make_unique<ExactRasterizer>(options);
  }
  return nullptr;
}

Status CreateRasterizer(const std::string& name, const RasterizerOptions& options,
                        std::unique_ptr<DepthRasterizer>* rasterizer) {
  RasterizerType type;
  if (!StringToRasterizerType(name, &type)) {
    return Status::InvalidArgument("unknown rasterizer '" + name + "'; valid: " +
                                   ValidRasterizerNames());
  }
  std::string why;
  if (!options.Check(&why)) return Status::InvalidArgument("rasterizer options: " + why);
  *rasterizer = CreateRasterizer(type, options);
  return Status::Ok();
}

Status DepthRasterizer::RenderNoEstimateNaN(const CorridorGeometry& geometry, const Camera& camera,
                                            cv::Mat* depth) const {
  const Status status = Render(geometry, camera, depth);
  if (status.ok()) MarkNoEstimateNaN(depth);
  return status;
}

Status CheckGeometryForRendering(const CorridorGeometry& g) {
  const double values[] = {g.yaw, g.pitch, g.offset, g.width, g.camera_height, g.ceiling_height};
  for (double x : values) {
    if (!std::isfinite(x)) return Status::InvalidArgument("geometry has a non-finite value");
  }
  if (g.width <= 0 || g.camera_height <= 0) {
    return Status::InvalidArgument("geometry needs a positive width and camera height");
  }
  if (g.LeftDistance() <= 0 || g.RightDistance() <= 0) {
    return Status::ImplausibleGeometry("the camera is not between the walls");
  }
  if (std::abs(g.yaw) >= M_PI / 2 || std::abs(g.pitch) >= M_PI / 2) {
    return Status::ImplausibleGeometry("yaw or pitch at or beyond 90 degrees");
  }
  return Status::Ok();
}

}  // namespace corridor
