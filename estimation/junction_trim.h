#pragma once

// The points of a junction that lie on the fitted corridor's lines, for the solvers that refit
// without the others (SolverOptions::trim_sigmas), and the points' robust spread about those lines
// (SolverOptions::loss_sigmas).

#include <cstddef>
#include <vector>

#include "corridor_depth/corridor_observation.h"
#include "corridor_depth/virtual_camera.h"

namespace corridor {

// The least robust standard deviation of the points' distances, px: a guard for points without
// spread (points sampled on a fitted line lie on it to round-off), far below the tenth of a pixel
// to which edge points are placed.
constexpr double kMinSigmaPx = 1e-3;

// Each side's points within trim_sigmas robust standard deviations (each at least kMinSigmaPx) of
// the lines of x = (yaw, pitch, offset, width), into *kept (whose vectors keep their memory; its
// camera is all's) with their weights and *mask (1 = kept, the left side's points then the
// right's). Distances are weighted (sqrt(w) |r|, in units of one point of average noise). False,
// keeping nothing, when a side would keep fewer than two points.
bool TrimToFit(const CorridorObservation& all, const FloorIntrinsics& intrinsics, const double x[4],
               double trim_sigmas, CorridorObservation* kept, std::vector<char>* mask);

// The buffers of a trimming loop (the kept points, this round's mask and the last round's), the
// calling thread's, reused from call to call.
struct TrimBuffers {
  CorridorObservation kept;
  std::vector<char> mask, previous;
};

// The thread's TrimBuffers, with `previous` set to keep all of `points` points.
TrimBuffers& ThreadTrimBuffers(size_t points);

// The robust standard deviation of the points' weighted distances (sqrt(w) |r|) from the lines
// of x: 1.4826 times their median, over the left side's points (which < 0), the right's
// (which > 0) or both (0). False when a line is at infinity or there are no points.
bool RobustSigma(const CorridorObservation& observation, const FloorIntrinsics& intrinsics,
                 const double x[4], int which, double* sigma);

}  // namespace corridor
