#include "perception/junction_candidates.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace corridor {

JunctionScenePrior MakeJunctionScenePrior(const JunctionDetectorOptions& options, int width,
                                          int height) {
  const double diagonal = std::hypot(width, height);
  JunctionScenePrior prior;
  prior.min_length = options.min_length_fraction * height;
  prior.max_length =
      options.max_length_fraction > 0 ? options.max_length_fraction * diagonal : 1e300;
  prior.min_inclination_deg = options.min_inclination_deg;
  prior.max_inclination_deg = options.max_inclination_deg >= 0
                                  ? options.max_inclination_deg
                                  : 90.0 - std::atan2(height, width) * 180.0 / M_PI;
  return prior;
}

void AddJunctionCandidates(const std::vector<MergedLine>& lines, double shortest,
                           const JunctionScenePrior& prior, const FloorCues& cues,
                           PairSearch* search) {
  search->left.reserve(search->left.size() + lines.size());
  search->right.reserve(search->right.size() + lines.size());
  for (const auto& line : lines) {
    if (line.length < shortest || line.length > prior.max_length) continue;
    if (line.inclination_deg < prior.min_inclination_deg ||
        line.inclination_deg > prior.max_inclination_deg) {
      continue;
    }
    const double boundary = BoundaryScore(cues.roi, cues.floor, line, cues.roi_top, cues.scale);
    (line.slope < 0 ? search->left : search->right).push_back({line, boundary});
  }
}

void SelectPair(const Eigen::Vector2d& size, const BaseboardBandTest& band, const FloorCues& cues,
                PairSearch* search) {
  if (search->left.empty() || search->right.empty()) return;
  search->pair =
      SelectJunctionPair(&search->left, &search->right, search->lines, size, band,
                         cues.floor_band);
}

void FirstLook(const std::vector<cv::Vec4f>& segments, const JunctionDetectorOptions& options,
               const JunctionScenePrior& prior, const FloorCues& cues,
               const Eigen::Vector2d& size, const BaseboardBandTest& band, PairSearch* search) {
  MergeSegments(segments, options.merge_angle_deg, options.merge_distance_px, &search->lines);
  search->left.clear();
  search->right.clear();
  search->pair = SelectedPair();
  AddJunctionCandidates(search->lines, prior.min_length, prior, cues, search);
  SelectPair(size, band, cues, search);
}

bool SecondLook(const EdgeSegments& found, const SegmentOptions& segment_options,
                const JunctionSearchRegion& region, const JunctionDetectorOptions& options,
                const JunctionScenePrior& prior, const FloorCues& cues,
                const Eigen::Vector2d& size, const BaseboardBandTest& band, PairSearch* first,
                std::vector<cv::Vec4f>* segments) {
  const double height = size.y();
  SegmentOptions relaxed = segment_options;
  relaxed.hough_threshold = options.relaxed_hough_threshold;
  relaxed.hough_min_length =
      std::max(8.0, options.relaxed_hough_min_length_fraction * height / region.scale);
  std::vector<cv::Vec4f> found_segments = HoughSegments(found, relaxed);
  SegmentsToImage(region, &found_segments);
  PairSearch second;
  second.lines = MergeSegments(found_segments, options.merge_angle_deg, options.merge_distance_px);
  AddJunctionCandidates(second.lines,
                        std::max(prior.min_length, options.relaxed_min_line_fraction * height),
                        prior, cues, &second);
  // The second look's lines first, then the first look's: an index below these counts is new.
  const int new_left = static_cast<int>(second.left.size());
  const int new_right = static_cast<int>(second.right.size());
  second.left.insert(second.left.end(), first->left.begin(), first->left.end());
  second.right.insert(second.right.end(), first->right.begin(), first->right.end());
  SelectPair(size, band, cues, &second);
  const SelectedPair& p = second.pair;
  // A band's lower edge found from colours is as new as the line above it.
  const auto is_new = [](const std::vector<JunctionCandidate>& side, int chosen, int count) {
    const int line = chosen >= 0 && side[chosen].foot_of >= 0 ? side[chosen].foot_of : chosen;
    return line < count;
  };
  const bool left_new = is_new(second.left, p.left, new_left);
  const bool right_new = is_new(second.right, p.right, new_right);
  if (p.left >= 0 && left_new != right_new &&
      (left_new ? second.right[p.right] : second.left[p.left]).boundary >=
          options.relaxed_min_partner_boundary) {
    *first = std::move(second);
    *segments = std::move(found_segments);
    return true;
  }
  return false;
}

}  // namespace corridor
