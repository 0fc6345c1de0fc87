#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "perception/line_segments.h"

namespace corridor {

// A candidate junction with its cues.
struct JunctionCandidate {
  MergedLine line;      // The merged line.
  double boundary = 0;  // BoundaryScore in [0, 1]: floor below, something else above.
};

// The chosen pair and why.
struct SelectedPair {
  int left = -1, right = -1;  // Indices into the candidate lists; -1 when none.
  Eigen::Vector2d vanishing_point = Eigen::Vector2d::Zero();
  double score = 0;  // The pair's score.
  // Per side, a line below the chosen one (within 12 degrees, through the same vanishing point, on
  // the floor side, with at least half its boundary score within 6 degrees, 0.4 of it beyond)
  // that the baseboard rule did not take: the junction if the chosen line is a baseboard top, or
  // a recess's floor line, after all. -1 when there is none. Another cue (the ceiling) decides.
  int left_lower = -1, right_lower = -1;
};

// The baseboard rule's second test: the band between a side's chosen line and a lower partner.
struct BaseboardBandTest {
  // How unlike the floor below it the band between `upper` and `lower` looks (BandContrast);
  // empty: no band test.
  std::function<double(const MergedLine& upper, const MergedLine& lower)> contrast;
  double min_contrast = 1.45;       // At least this: the band is a baseboard, the partner the junction.
  double min_boundary_ratio = 0.3;  // Partners with less of the chosen line's boundary score are not tried.
};

// Scores every (left, right) pair: both lines' support lengths and boundary scores, plus the
// agreement of the other lines with the pair's vanishing point. A pair must meet above both
// supports, with the left support left of the vanishing point and the right support right of it.
// `all_lines` are every merged line (for the vanishing-point vote); `size` is (width, height).
// Then, per side, the baseboard rule: a lower partner of the chosen line becomes the junction when
// its boundary score nearly matches the chosen line's, or when `band` finds the band between them
// unlike the floor (a baseboard whose lower edge has little contrast with the floor).
SelectedPair SelectJunctionPair(const std::vector<JunctionCandidate>& left,
                                const std::vector<JunctionCandidate>& right,
                                const std::vector<MergedLine>& all_lines,
                                const Eigen::Vector2d& size,
                                const BaseboardBandTest& band = BaseboardBandTest());

}  // namespace corridor
