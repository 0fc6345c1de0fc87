#pragma once

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"

namespace corridor {

// The depth rasterisers: they take only a corridor geometry and a camera, never an image.
enum class RasterizerType {
  kPaper,  // "paper": depth planes through pairs of junction points, interpolated (paper III-C.3).
  kExact,  // "exact": the box model's closed-form depth of every pixel (docs/geometry.md 3, 6).
};

const char* RasterizerTypeToString(RasterizerType type);
bool StringToRasterizerType(const std::string& name, RasterizerType* type);
std::string ValidRasterizerNames();

struct RasterizerOptions {
  double max_range = 40.0;  // Depth beyond this gets 0 (no estimate), m (the paper's far range).
  double max_height = 2.5;  // Without a ceiling estimate, wall points higher than this above the floor get 0, m.
  bool use_ceiling = true;  // Render the ceiling plane when the geometry has a ceiling height.
  int paper_planes = 96;    // "paper": number of depth planes between the nearest visible floor and max_range.
  bool use_avx2 = true;     // "exact": AVX2 rows where the CPU has it (the same depths as the baseline rows; false = baseline).
  bool plane_spans = true;  // "exact": each row's run where the floor or ceiling is surely nearest is filled without per-pixel divisions (the same depths; false = every pixel divides).

  bool Check(std::string* why) const;
};

class DepthRasterizer {
 public:
  virtual ~DepthRasterizer() = default;
  virtual std::string Name() const = 0;
  // Writes a CV_32F depth image (metres, camera-frame z, 0 = no estimate) of the camera's size.
  virtual Status Render(const CorridorGeometry& geometry, const Camera& camera,
                        cv::Mat* depth) const = 0;
  // The same depths with NaN for no estimate (every pixel Render leaves not positive), as the
  // pipeline reports them: Render's image marked afterwards, unless a rasteriser writes NaN in
  // its own pass.
  virtual Status RenderNoEstimateNaN(const CorridorGeometry& geometry, const Camera& camera,
                                     cv::Mat* depth) const;
};

std::unique_ptr<DepthRasterizer> CreateRasterizer(RasterizerType type,
                                                  const RasterizerOptions& options);
// By name; checks the options; an unknown name lists the valid ones.
Status CreateRasterizer(const std::string& name, const RasterizerOptions& options,
                        std::unique_ptr<DepthRasterizer>* rasterizer);

// Validates a geometry for rendering (finite, positive width and height, camera between walls).
Status CheckGeometryForRendering(const CorridorGeometry& geometry);

}  // namespace corridor
