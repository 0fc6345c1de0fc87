#pragma once

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/corridor_geometry.h"
#include "perception/junction_lines.h"

namespace corridor {

// Door frames, wall corners, lockers' and baseboards' ends are vertical and stop at the floor:
// where such an edge meets a true floor/wall junction from above, the floor lies below it. A
// handrail, chair rail, wainscot top, window sill or bench edge taken for the junction is crossed
// by them instead: the wall, and its vertical edges, go on below the line. This counts, along a
// junction, the places where a vertical edge runs down to it from above, and those where one also
// goes on below it.
struct VerticalCrossings {
  int reaching = 0;  // Vertical edges that run down to the junction from above.
  int crossing = 0;  // Of those, the ones that go on below it.
  int samples = 0;   // Points of the junction that were examined.
  // crossing / reaching; 0 when fewer than `min_reaching` edges reach the junction.
  double CrossingFraction(int min_reaching = 2) const {
    return reaching >= min_reaching ? static_cast<double>(crossing) / reaching : 0.0;
  }
};

struct VerticalCrossingOptions {
  double band_height = 0.25;        // How far above (and as far in pixels below) the junction to look, m on the wall.
  double min_band_px = 5;           // Junction points whose band is shorter are not examined, px.
  double max_band_px = 24;          // Longer bands (near the camera) are cut to this, px.
  double min_step = 8;              // An edge is a step of at least this many grey levels in each channel.
  double min_run = 0.7;             // A vertical edge must cover this fraction of a band.
  double min_contrast_ratio = 0.7;  // Below the junction, an edge of less than this fraction of the contrast above is a reflection.
  int step_px = 2;                  // Junction points every this many pixels.
  bool Check(std::string* why) const;
};

// The crossings of the floor/wall junction that `geometry` puts on a wall, over the extent of
// `line` (raw pixels of the full image; `scale` full-image pixels per pixel of `bgr`), in the
// 8-bit BGR `bgr` seen by `camera` (of bgr's size). The gradients are computed only on the bands
// examined (a few thousand pixels), from the colour image's channel sum.
VerticalCrossings CountVerticalCrossings(const cv::Mat& bgr, const Camera& camera, int scale,
                                         const CorridorGeometry& geometry, const JunctionLine& line,
                                         const VerticalCrossingOptions& options);

}  // namespace corridor
