#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/corridor_geometry.h"
#include "core/status.h"
#include "perception/oriented_edges.h"

namespace corridor {

// Finding a wall across the corridor once the side walls are known (beyond the paper): the
// floor/end-wall junction is the line (X, h, D), -d_l <= X <= d_r, of the corridor frame. It must
// follow the image's edges over two thirds of the width at least, and a floor/wall junction must end there
// (their continuation behind it is hidden), and at least one vertical wall/end-wall corner must
// show, and the wall above the line must look unlike the floor before it. Tile grout and door
// sills across the floor follow the edges too, but the junctions go on beyond them, they have no
// corners and floor lies on both sides: they are not taken for an end wall.
struct EndWallDetectorOptions {
  double near_distance = 1.5;  // Nearest end wall considered, m along the corridor.
  double far_distance = 20.0;  // Farthest, m (farther, the floor/end-wall line is too few pixels to tell).
  int candidates = 0;          // Candidate distances, uniform in 1/D between near and far (0 = as many as reach_px needs).
  int samples = 60;            // Samples along each searched line.
  double min_support = 0.6;    // Fraction of the floor/end-wall line's samples on edges, in two of its thirds.
  double max_beyond = 0.3;     // Largest fraction of the cleaner junction's samples on edges just beyond the wall.
  double min_before = 0.4;     // Least fraction of a junction's samples on edges just before it (one side).
  double min_corner = 0.5;     // Least fraction of a vertical corner's samples on edges (one side).
  double min_contrast = 6.0;   // Least Lab distance (appearance.h) of the wall just above the line from the floor before it (0 = off).
  double min_span = 0.08;      // Visible length of the floor/end-wall line, as a fraction of the image width.
  int reach_px = 2;            // A sample is on an edge within this many px (the geometry is not exact).
  int max_work_width = 480;    // Wider images are searched at half resolution (or less), px.

  bool Check(std::string* why) const;
};

struct EndWallEstimate {
  bool found = false;   // True when an end wall was seen.
  double distance = 0;  // Its Z_W, m along the corridor from the camera (valid when found).
  double support = 0;   // The second-best third's fraction of the floor/end-wall line on edges.
  double beyond = 0;    // The cleaner junction's fraction on edges just beyond the wall.
  double corner = 0;    // The corners' largest fraction on edges.
  double before = 0;    // The junctions' largest fraction on edges just before the wall.
  int points = 0;       // Edge pixels whose rays gave the robust (median) distance.
  std::string reason;   // Why nothing was found.
};

// Searches the end wall's distance; then each edge pixel near the chosen floor/end-wall line
// gives D from its ray's intersection with the floor, and the median is the estimate. `bgr` is
// the raw image; the camera's distortion is honoured. Never fails on bad images: found is false
// with a reason. InvalidArgument for bad options or an image that is not the camera's size.
// `edges`: the image's edges when another search has them (ComputeImageEdges of `bgr`), used when
// the image is searched at its own resolution; else computed here.
Status DetectEndWall(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& geometry,
                     const EndWallDetectorOptions& options, EndWallEstimate* estimate,
                     const ImageEdges* edges = nullptr);

}  // namespace corridor
