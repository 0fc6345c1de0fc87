#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "perception/appearance.h"
#include "perception/floor_band.h"
#include "perception/line_segments.h"

namespace corridor {

// A candidate junction with its cues.
struct JunctionCandidate {
  MergedLine line;      // The merged line.
  double boundary = 0;  // BoundaryScore in [0, 1]: floor below, something else above.
  // A band's lower edge found from colours (BaseboardBandTest::lower_edge), not by the line
  // search: the candidate it lies below, and its turn from it about the vanishing point, degrees.
  int foot_of = -1;
  double foot_turn_deg = 0;
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
  // Per side, the line the pair chose when the floor or stripe rule replaced it by one above; -1
  // otherwise.
  int left_inner = -1, right_inner = -1;
};

// The baseboard rule's second test: the band between a side's chosen line and a lower partner.
struct BaseboardBandTest {
  // How unlike the floor below it the band between `upper` and `lower` looks (BandContrast);
  // empty: no band test.
  std::function<double(const MergedLine& upper, const MergedLine& lower)> contrast;
  double min_contrast = 1.45;       // At least this: the band is a baseboard, the partner the junction.
  double min_boundary_ratio = 0.3;  // Partners with less of the chosen line's boundary score are not tried.
  // Where no line below the chosen one is a partner, the band's lower edge found from the image's
  // colours along candidate lines (FindLowerEdge, turned by up to `max_angle_deg`); false when
  // there is none. Empty: not looked for. The band test above decides.
  std::function<bool(const MergedLine& chosen, const Eigen::Vector2d& vanishing_point, bool left,
                     double max_angle_deg, JunctionCandidate* lower)>
      lower_edge;
  // The boundary score (BoundaryScore) of a lower edge taken; empty: 0.
  std::function<double(const MergedLine& line)> boundary;
};

// The floor rule: the band between a side's chosen line and a line above it (on the wall side,
// through the same vanishing point) is floor, not wall, when its edges run across the corridor
// (tile joints reach the wall) and none stand vertical (a wall's door frames and corners do), or
// when it has a carpet's texture: the chosen line is then a runner's or a stripe's edge inside the
// floor, and the line above bounds it.
struct FloorBandTest {
  // The band's edges (MeasureBandEdges); empty: no floor rule.
  std::function<BandEdges(const MergedLine& inner, const MergedLine& outer,
                          const Eigen::Vector2d& vanishing_point)>
      measure;
  // The outer line's boundary score (BoundaryScore) against the floor just below it: it stands in
  // for the score against the reference patch, which may show the runner, not this floor, when
  // it is higher.
  std::function<double(const MergedLine& outer)> boundary;
  long min_across = 20;             // At least this many edge pixels across the corridor...
  int min_across_rows = 4;          // ... on at least this many rows (joints recur down a floor)...
  double max_vertical_ratio = 0.1;  // ... and at most this many vertical ones per across one.
                                    // 0 min_across: no floor rule (the stripe rule may still run).
  // Or the band is a textured floor (carpet): edges in every direction, so mostly oblique ones
  // (an isotropic texture has about three times as many as vertical or across ones; a wall's
  // edges stand vertical or run along the corridor), on at least min_across_rows rows.
  double min_texture_density = 0.05;  // Edge pixels per band pixel, at least; 0: no texture test.
  double min_oblique_ratio = 3.0;     // Oblique edge pixels per vertical and per across one.
  // The stripe rule: the floor just below a line (SampleBelowLine), and how much the strip just
  // above a line looks like it (FloorLikenessAbove); either empty: no stripe rule. A stripe, a
  // border or a runner's edge painted or laid beside the wall has floor beyond it; the junction
  // has wall.
  std::function<FloorAppearance(const MergedLine& line)> floor_below;
  std::function<double(const FloorAppearance& floor, const MergedLine& line)> floor_above;
  // The stripe rule also runs from the floor rule's line, right after the floor rule moved, with
  // the floor just below that line (the floor band's own material, not the runner's).
  bool stripe_beyond_floor_band = true;
  // ... and, when the floor rule moved on one side only, on the other side from a line with the
  // same floor below it (a runner's other edge), with the first side's floor band colour.
  bool runner_other_side = true;
  double stripe_max_inner = 0.35;  // The chosen line shows at most this much floor above it...
  double stripe_min_beyond = 0.7;  // ... and a line above it at least this much: the floor goes
                                   // on beyond that line, and the next line above bounds it.
  // The inside-floor rule: a chosen line with at least this much floor above it lies inside the
  // floor, and the nearest line above it becomes the chosen line; 0: no inside-floor rule.
  double inside_min_likeness = 0;
  // ... or at least `ridge_min_likeness` (0: no such relaxation) when the chosen line is a thin
  // ridge, a joint darker or lighter than the floor on both its sides, along at least
  // `min_ridge_fraction` of it (`ridge`: RidgeFraction; empty: no relaxation). A reflection on a
  // satin floor makes the strip beyond a joint near the wall a little less alike. Then the line
  // taken is the nearest one above farther than `ridge_width_px` (nearer ones are the joint's own
  // other edge), and the band up to it must have at most `ridge_max_vertical_ratio` vertical edge
  // pixels per across one (a wall's door frames and corners stand vertical; a reflecting floor
  // mirrors a few of them, between its joints).
  std::function<double(const MergedLine& line)> ridge;
  double ridge_min_likeness = 0;
  double min_ridge_fraction = 0.4;
  double ridge_width_px = 4;
  double ridge_max_vertical_ratio = 2;
};

// Scores every (left, right) pair: both lines' support lengths and boundary scores, plus the
// agreement of the other lines with the pair's vanishing point. A pair must meet above both
// supports, with the left support left of the vanishing point and the right support right of it.
// `all_lines` are every merged line (for the vanishing-point vote); `size` is (width, height).
// Then, per side, the baseboard rule: a lower partner of the chosen line becomes the junction when
// its boundary score nearly matches the chosen line's, or when `band` finds the band between them
// unlike the floor (a baseboard whose lower edge has little contrast with the floor); where no
// line lies below, the band's lower edge from the colours (`band.lower_edge`), under the same
// band test and unless the band's edges say floor, is appended to the side's candidates and
// chosen (JunctionCandidate::foot_of). Before it,
// the floor rule (`floor_band`): the nearest line above the chosen one whose band is floor
// becomes the chosen line, its boundary score the higher of the two (`floor_band.boundary`); when
// it moved, the stripe rule from its line with the floor band's own colour
// (`floor_band.stripe_beyond_floor_band`), and the baseboard rule then never steps back to or
// inside that stripe's far edge.
// After both, the stripe rule (`floor_band.floor_above`): when the floor goes on above a line
// beyond the chosen one, the next line above that one becomes the chosen line. Last, the
// inside-floor rule (`floor_band.inside_min_likeness`): a chosen line with floor colour above it
// as well as below gives way to the nearest line above it (or, a little less alike above, a
// joint's ridge: `floor_band.ridge`).
SelectedPair SelectJunctionPair(std::vector<JunctionCandidate>* left,
                                std::vector<JunctionCandidate>* right,
                                const std::vector<MergedLine>& all_lines,
                                const Eigen::Vector2d& size,
                                const BaseboardBandTest& band = BaseboardBandTest(),
                                const FloorBandTest& floor_band = FloorBandTest());

}  // namespace corridor
