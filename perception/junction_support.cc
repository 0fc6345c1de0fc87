#include "perception/junction_support.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "perception/junction_detector.h"
#include "perception/junction_memory.h"
#include "perception/robust_line_fit.h"
#include "perception/support_extent.h"

namespace corridor {
namespace {

// The points of `from` for which keep(p) holds, in order, into *to. Every point is written and
// the count advanced only for the kept ones: no branch on where the points lie, which edge maps
// make unpredictable.
template <typename Keep>
void KeepWhere(const std::vector<Eigen::Vector2d>& from, Keep keep,
               std::vector<Eigen::Vector2d>* to) {
  to->resize(from.size());
  size_t kept = 0;
  for (const auto& p : from) {
    (*to)[kept] = p;
    kept += static_cast<size_t>(keep(p));
  }
  to->resize(kept);
}

// RefineJunction's working memory.
struct RefineScratch {
  std::vector<Eigen::Vector2d> side, near, fitted;
  std::vector<int> bins;
};

}  // namespace

std::vector<Eigen::Vector2d> FloorSidePixels(const std::vector<Eigen::Vector2d>& edges,
                                             const Eigen::Vector2d& vp, bool left) {
  std::vector<Eigen::Vector2d> side;
  FloorSidePixels(edges, vp, left, &side);
  return side;
}

void FloorSidePixels(const std::vector<Eigen::Vector2d>& edges, const Eigen::Vector2d& vp,
                     bool left, std::vector<Eigen::Vector2d>* side) {
  KeepWhere(
      edges, [&](const Eigen::Vector2d& p) {
        const bool beyond = left ? p.x() > vp.x() : p.x() < vp.x();
        return !beyond & !(p.y() < vp.y());
      },
      side);
}

void SupportPixels(const std::vector<Eigen::Vector2d>& side, const Eigen::Vector3d& line,
                   double distance, std::vector<Eigen::Vector2d>* support) {
  KeepWhere(
      side, [&](const Eigen::Vector2d& p) {
        return !(std::abs(line.dot(p.homogeneous())) > distance);
      },
      support);
}

JunctionLine RefineJunction(const JunctionCandidate& candidate,
                            const std::vector<Eigen::Vector2d>& edges, const Eigen::Vector2d& vp,
                            bool left, double distance, double image_height) {
  JunctionLine out;
  Eigen::Vector3d line = candidate.line.line;
  // The side's pixels, the last fit's and the support's positions along the line in the thread's
  // scratch, which keeps its memory from call to call; `support` becomes the result's (a spare
  // result's memory, junction_memory.h).
  thread_local RefineScratch thread_scratch;
  RefineScratch& scratch = thread_scratch;
  std::vector<Eigen::Vector2d>& side = scratch.side;
  FloorSidePixels(edges, vp, left, &side);
  std::vector<Eigen::Vector2d> support = SpareSupport();
  std::vector<Eigen::Vector2d>& fitted = scratch.fitted;  // The pixels `line` was fitted to.
  fitted.clear();
  bool final_support = false;  // True once `support` is the final (distance, line) support.
  // The side's pixels within 2 distance + kSlack of the candidate: a support of a line that moved
  // less than the rest of that reach over the side's extent (|a' - a| max|u| + |b' - b| max|v| +
  // |c' - c|, a bound on how far any pixel's distance moved) has no pixel outside them, so it is
  // found among them alone; else among all.
  constexpr double kSlack = 8.0;
  const Eigen::Vector3d first_line = line;
  const double reach = 2 * distance + kSlack;
  double max_u = 0, max_v = 0;
  for (const Eigen::Vector2d& p : side) {
    max_u = std::max(max_u, std::abs(p.x()));
    max_v = std::max(max_v, std::abs(p.y()));
  }
  std::vector<Eigen::Vector2d>& near = scratch.near;
  SupportPixels(side, first_line, reach, &near);
  const auto pixels_for = [&](const Eigen::Vector3d& l,
                              double d) -> const std::vector<Eigen::Vector2d>& {
    const Eigen::Vector3d moved = (l - first_line).cwiseAbs();
    const double bound = moved.x() * max_u + moved.y() * max_v + moved.z();
    return bound <= reach - d - 1e-6 ? near : side;  // 1e-6 px: more than rounding can move.
  };
  for (int round = 0; round < 3; ++round) {
    const double d = round == 0 ? 2 * distance : distance;
    SupportPixels(pixels_for(line, d), line, d, &support);
    // The same pixels give the same fit (FitLineLeastDistance is deterministic): the line has
    // converged.
    if (round > 0 && support == fitted) {
      final_support = true;
      break;
    }
    Eigen::Vector3d refit;
    if (!FitLineLeastDistance(support, &refit)) break;
    line = refit;
    fitted.swap(support);
  }
  if (!final_support) SupportPixels(pixels_for(line, distance), line, distance, &support);
  out.line = line;
  const Eigen::Vector2d direction(line.y(), -line.x());
  const Eigen::Vector2d origin = -line.z() * line.head<2>();
  if (support.size() < 8) {
    support = {candidate.line.start, candidate.line.end};
  }
  const SupportExtent extent = MeasureSupport(support, line, &scratch.bins);
  const double lo = extent.lo, hi = extent.hi;
  out.support_length = static_cast<double>(extent.covered);
  const Eigen::Vector2d a = origin + lo * direction, b = origin + hi * direction;
  // The near end is the lower one (larger v).
  out.near_end = a.y() > b.y() ? a : b;
  out.far_end = a.y() > b.y() ? b : a;
  out.support = std::move(support);
  out.confidence = JunctionConfidence(candidate.boundary, out.support_length, image_height);
  return out;
}

}  // namespace corridor
