#pragma once

#include <vector>

#include <Eigen/Core>

#include "perception/line_segments.h"

namespace corridor {

// A candidate junction with its cues.
struct JunctionCandidate {
  MergedLine line;        // The merged line.
  double boundary = 0;    // BoundaryScore in [0, 1]: floor below, something else above.
};

// The chosen pair and why.
struct SelectedPair {
  int left = -1, right = -1;  // Indices into the candidate lists; -1 when none.
  Eigen::Vector2d vanishing_point = Eigen::Vector2d::Zero();
  double score = 0;           // The pair's score.
  // Per side, a line just below the chosen one (within 6 degrees, through the same vanishing
  // point, on the floor side) that the baseboard rule did not take: the junction if the chosen
  // line is a baseboard top after all. -1 when there is none. Another cue (the ceiling) decides.
  int left_lower = -1, right_lower = -1;
};

// Scores every (left, right) pair: both lines' support lengths and boundary scores, plus the
// agreement of the other lines with the pair's vanishing point. A pair must meet above both
// supports, with the left support left of the vanishing point and the right support right of it.
// `all_lines` are every merged line (for the vanishing-point vote); `size` is (width, height).
SelectedPair SelectJunctionPair(const std::vector<JunctionCandidate>& left,
                                const std::vector<JunctionCandidate>& right,
                                const std::vector<MergedLine>& all_lines,
                                const Eigen::Vector2d& size);

}  // namespace corridor
