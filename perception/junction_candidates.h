#pragma once

// Private to the junction detector: the lines that may be junctions, and the pair chosen among
// them, from the first Hough look and, when it finds no pair, a second, relaxed one.

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "perception/appearance.h"
#include "perception/junction_detector.h"
#include "perception/junction_search_region.h"
#include "perception/junction_selector.h"
#include "perception/line_segments.h"

namespace corridor {

// The paper's scene prior (eq. 2) on a junction's length and inclination, in image pixels.
struct JunctionScenePrior {
  double min_length = 0;            // Shortest junction, px.
  double max_length = 1e300;        // Longest junction, px.
  double min_inclination_deg = 0;   // Flattest junction, degrees from horizontal.
  double max_inclination_deg = 90;  // Steepest junction, degrees from horizontal.
};

// The prior of `options` for an image width x height. A negative max_inclination_deg reads the
// paper's 90 deg - atan(H/W), with theta measured from the vertical image axis: steeper lines are
// door frames and pillars, not junctions.
JunctionScenePrior MakeJunctionScenePrior(const JunctionDetectorOptions& options, int width,
                                          int height);

// What tells a junction from other lines: the floor's appearance in the search region.
struct FloorCues {
  cv::Mat roi;  // The colour image's rows [roi_top, rows).
  FloorAppearance floor;
  int roi_top = 0;
  int scale = 1;             // The search's working scale (BoundaryScore's probe spacing).
  FloorBandTest floor_band;  // The selector's floor rule (none when its measure is empty).
};

// The lines that may be junctions, per side, and the best pair of them.
struct PairSearch {
  std::vector<MergedLine> lines;               // Every merged line.
  std::vector<JunctionCandidate> left, right;  // Those the prior admits, by their slope's side.
  SelectedPair pair;                           // Indices into left and right; -1 when none.
};

// Appends to `search`'s sides the lines of `lines` at least `shortest` px long that `prior`
// admits, each with its BoundaryScore.
void AddJunctionCandidates(const std::vector<MergedLine>& lines, double shortest,
                           const JunctionScenePrior& prior, const FloorCues& cues,
                           PairSearch* search);

// SelectJunctionPair on `search`'s sides, in an image of `size` (width, height); nothing when a
// side is empty.
void SelectPair(const Eigen::Vector2d& size, const BaseboardBandTest& band, const FloorCues& cues,
                PairSearch* search);

// The first look: `segments` (image pixels) merged, their candidates and the best pair, into
// *search (replaced; its vectors' memory kept).
void FirstLook(const std::vector<cv::Vec4f>& segments, const JunctionDetectorOptions& options,
               const JunctionScenePrior& prior, const FloorCues& cues,
               const Eigen::Vector2d& size, const BaseboardBandTest& band, PairSearch* search);

// The second look for shorter pieces (the relaxed Hough options on the same edges), when the
// first found no pair: a faint junction broken by door bottoms gives pieces too short for the
// first Hough, which merge into one line. Its pair is taken only when it pairs one new line, at
// least relaxed_min_line_fraction of the height long, with a first-look line whose boundary score
// is at least relaxed_min_partner_boundary: blob outlines of outdoor scenes give short straight
// pieces that line up by chance too. True, with *first replaced and *segments the second look's
// segments (image pixels), when it is taken.
bool SecondLook(const EdgeSegments& found, const SegmentOptions& segment_options,
                const JunctionSearchRegion& region, const JunctionDetectorOptions& options,
                const JunctionScenePrior& prior, const FloorCues& cues,
                const Eigen::Vector2d& size, const BaseboardBandTest& band, PairSearch* first,
                std::vector<cv::Vec4f>* segments);

}  // namespace corridor
