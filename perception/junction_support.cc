#include "perception/junction_support.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

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
  std::vector<Eigen::Vector2d> ends[2];  // A support's nearest and farthest thirds (UnbendLine).
  std::vector<double> along;
};

// The least step, px, between the two ends of a line's support (each end's pixels from the other
// end's fit) that makes it two edges: one straight edge's pixels scatter by well under a
// pixel about its fit, and the next edge beside a junction (a grout line, a baseboard's top) lies
// a few pixels off.
constexpr double kMinBendStepPx = 1.5;

// Each end's pixels lie within `distance` of the bent line, so two edges it bends between are a
// few distances apart: a larger step is two ends' fits thrown apart (short ends, or pixels of
// another structure, a door's foot, at one end), not a bend.
constexpr double kMaxBendSteps = 3.0;

// Within this of a line, px, an edge pixel is on it when lines are compared by their pixels: one
// straight edge's pixels lie within it, and a line bent between two edges loses those of both.
constexpr double kOnLinePx = 1.0;

// How many of `pixels` lie within `distance` of each of the three `lines` and, along
// `direction`, in [lo, hi]: counts[i] for lines[i], in one pass.
void CountNear(const std::vector<Eigen::Vector2d>& pixels, const Eigen::Vector3d (&lines)[3],
               double distance, const Eigen::Vector2d& direction, double lo, double hi,
               long counts[3]) {
  long n0 = 0, n1 = 0, n2 = 0;
  for (const Eigen::Vector2d& p : pixels) {
    const double t = p.dot(direction);
    const bool along = (t >= lo) & (t <= hi);
    n0 += !(std::abs(lines[0].dot(p.homogeneous())) > distance) & along;
    n1 += !(std::abs(lines[1].dot(p.homogeneous())) > distance) & along;
    n2 += !(std::abs(lines[2].dot(p.homogeneous())) > distance) & along;
  }
  counts[0] = n0, counts[1] = n1, counts[2] = n2;
}

// The median of |line . p| over `pixels` (not empty); `buffer` is working memory.
double MedianDistance(const std::vector<Eigen::Vector2d>& pixels, const Eigen::Vector3d& line,
                      std::vector<double>* buffer) {
  buffer->clear();
  for (const Eigen::Vector2d& p : pixels) buffer->push_back(std::abs(line.dot(p.homogeneous())));
  const auto middle = buffer->begin() + static_cast<std::ptrdiff_t>(buffer->size() / 2);
  std::nth_element(buffer->begin(), middle, buffer->end());
  return *middle;
}

// A line fitted across two edges (a junction over part of its length, a grout line or a
// baseboard's top a few pixels beside it over the rest) bends between them: the fits of its
// support's nearest and farthest thirds each follow one edge, and each third's pixels lie a step
// off the other third's fit. Then, of the line and the two thirds' fits, the one with the most of
// `side`'s pixels on it (within kOnLinePx) over the support's extent (the edge that runs the
// whole way) is refitted on its pixels within `distance` into *line and *support. False, with
// nothing changed, for a straight support.
bool UnbendLine(const std::vector<Eigen::Vector2d>& side, double distance, Eigen::Vector3d* line,
                std::vector<Eigen::Vector2d>* support, RefineScratch* scratch) {
  if (support->size() < 24) return false;
  const Eigen::Vector2d direction(line->y(), -line->x());
  std::vector<double>& along = scratch->along;
  along.clear();
  for (const Eigen::Vector2d& p : *support) along.push_back(p.dot(direction));
  const auto [first, last] = std::minmax_element(along.begin(), along.end());
  const double lo = *first, hi = *last;
  const size_t third = along.size() / 3;
  std::nth_element(along.begin(), along.begin() + static_cast<std::ptrdiff_t>(third), along.end());
  const double low = along[third];
  std::nth_element(along.begin(), along.end() - static_cast<std::ptrdiff_t>(third) - 1,
                   along.end());
  const double high = along[along.size() - third - 1];
  std::vector<Eigen::Vector2d>* ends = scratch->ends;
  ends[0].clear();
  ends[1].clear();
  for (const Eigen::Vector2d& p : *support) {
    const double t = p.dot(direction);
    if (t < low) ends[0].push_back(p);
    if (t > high) ends[1].push_back(p);
  }
  Eigen::Vector3d fits[2];
  for (int e = 0; e < 2; ++e) {
    if (ends[e].size() < 8 || !FitLineLeastDistance(ends[e], &fits[e])) return false;
  }
  double step = 0;
  for (int e = 0; e < 2; ++e) {
    step = std::max(step, MedianDistance(ends[e], fits[1 - e], &along));
  }
  if (step < kMinBendStepPx || step > kMaxBendSteps * distance) return false;
  // Over the support's own extent: which line the pixels there follow, not which edge runs on
  // further (a rail or a baseboard's top beyond a junction's hidden stretch).
  const Eigen::Vector3d lines[3] = {*line, fits[0], fits[1]};
  long counts[3];
  CountNear(side, lines, kOnLinePx, direction, lo, hi, counts);
  long most = counts[0];
  const Eigen::Vector3d* best = nullptr;
  for (int e = 0; e < 2; ++e) {
    if (counts[e + 1] > most) most = counts[e + 1], best = &fits[e];
  }
  if (best == nullptr) return false;
  Eigen::Vector3d unbent = *best;
  for (int round = 0; round < 2; ++round) {
    SupportPixels(side, unbent, distance, support);
    Eigen::Vector3d refit;
    if (!FitLineLeastDistance(*support, &refit)) break;
    unbent = refit;
  }
  SupportPixels(side, unbent, distance, support);
  *line = unbent;
  return true;
}

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
  UnbendLine(side, distance, &line, &support, &scratch);
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
