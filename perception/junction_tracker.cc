#include "perception/junction_tracker.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "perception/appearance.h"
#include "perception/junction_selector.h"
#include "perception/line_edge_points.h"
#include "perception/line_segments.h"
#include "perception/robust_line_fit.h"
#include "perception/working_image.h"

namespace corridor {
namespace {

// A line near the previous one, as offsets along the band's rows (columns): it crosses row
// (column) k at offset + slope * (k - middle) from the previous line.
struct BandLine {
  double offset = 0;
  double slope = 0;
  int votes = 0;
};

// What one band holds: its edge points and the rows (columns) searched.
struct Band {
  std::vector<EdgePeak> peaks;
  int searched = 0;
  double first = 0, last = 0;  // The first and last row (column) of the band.
  double middle() const { return 0.5 * (first + last); }
  double half() const { return std::max(1.0, 0.5 * (last - first)); }
};

// The lines the band's edge points support, best supported first. Each is the best of a vote
// over offsets (1 px bins) and slopes (1 px over half the band), scored on three neighbouring
// offset bins (points within about 1.5 px), among the points no earlier line took: a line takes
// the points within 2 px of it, and their votes are taken back. Lines of fewer than min_votes
// are not returned; at most max_lines are.
std::vector<BandLine> VoteForLines(const Band& band, int reach, int min_votes, int max_lines) {
  const int bins = 2 * reach + 1;
  // One cell more at the end takes the votes that fall outside the bins, so that the vote loop
  // has no branch.
  const int outside = bins * bins;
  std::vector<int> votes(bins * bins + 1, 0);
  const double middle = band.middle(), half = band.half();
  // A point at `step` (-1 .. 1: the band's first to last row) from the middle with `offset` lies,
  // for slope bin j, in offset bin floor(x) with x = offset - (j - reach) * step + reach + 0.5,
  // when 0 <= x < bins.
  const auto vote = [&](const EdgePeak& peak, int sign) {
    const double step = (peak.major - middle) / half;
    const double x0 = peak.offset + reach * step + reach + 0.5;
    int* cell = votes.data();
    for (int j = 0; j < bins; ++j) {
      const double x = x0 - j * step;
      const int i = static_cast<int>(x);
      cell[x >= 0 && i < bins ? j * bins + i : outside] += sign;
    }
  };
  for (const EdgePeak& peak : band.peaks) vote(peak, 1);
  std::vector<char> taken(band.peaks.size(), 0);
  int left = static_cast<int>(band.peaks.size());
  std::vector<BandLine> lines;
  while (static_cast<int>(lines.size()) < max_lines && left >= min_votes) {
    BandLine best;
    for (int j = 0; j < bins; ++j) {
      const int* row = &votes[j * bins];
      for (int i = 0; i < bins; ++i) {
        const int score = row[i] + (i > 0 ? row[i - 1] : 0) + (i + 1 < bins ? row[i + 1] : 0);
        if (score > best.votes) {
          best.votes = score;
          best.offset = i - reach;
          best.slope = (j - reach) / half;
        }
      }
    }
    if (best.votes < min_votes) break;
    lines.push_back(best);
    for (size_t k = 0; k < band.peaks.size(); ++k) {
      const EdgePeak& peak = band.peaks[k];
      if (taken[k] ||
          std::abs(peak.offset - best.offset - best.slope * (peak.major - middle)) > 2.0) {
        continue;
      }
      taken[k] = 1;
      --left;
      vote(peak, -1);
    }
  }
  return lines;
}

// A candidate: the junction it would be, and the merged line the selector judges.
struct TrackedCandidate {
  JunctionLine junction;
  MergedLine merged;
  double distance = 0;  // From the previous line: the band line's mean offset at the band's ends, px.
};

// Sets the junction's support to `support` (points on its line, sought on every `step_px`-th row
// or column), its ends to the support's extent and its support length to the pixels the support
// covers along the line, as the detector's: each point stands for the stretch of line between
// its row (column) and the next searched one.
void SetSupport(std::vector<Eigen::Vector2d> support, int step_px, JunctionLine* junction) {
  const Eigen::Vector3d& line = junction->line;
  double lo = 1e300, hi = -1e300;
  std::vector<int> bins;
  for (const auto& p : support) {
    const double t = PositionAlong(line, p);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    bins.push_back(static_cast<int>(std::floor(t)));
  }
  std::sort(bins.begin(), bins.end());
  const Eigen::Vector2d direction(line.y(), -line.x());
  const double major = CrossedByRows(line) ? std::abs(direction.y()) : std::abs(direction.x());
  const double per_point = std::max(1.0, step_px / std::max(major, 0.5));
  junction->support_length =
      std::min(std::max(0.0, hi - lo) + 1,
               per_point * static_cast<double>(std::unique(bins.begin(), bins.end()) - bins.begin()));
  const Eigen::Vector2d origin = -line.z() * line.head<2>();
  const Eigen::Vector2d a = origin + lo * direction, b = origin + hi * direction;
  junction->near_end = a.y() > b.y() ? a : b;  // The near end is the lower one.
  junction->far_end = a.y() > b.y() ? b : a;
  junction->support = std::move(support);
}

// The candidate fitted to `points`: the line of least distance to them, then again to those
// within support_distance_px of it; its extent and support length (distinct pixels along it) as
// the detector's. False with too few points.
bool FitCandidate(const std::vector<Eigen::Vector2d>& points, double support_distance, int step_px,
                  TrackedCandidate* candidate) {
  Eigen::Vector3d line;
  if (!FitLineLeastDistance(points, &line)) return false;
  std::vector<Eigen::Vector2d> support;
  for (const auto& p : points) {
    if (std::abs(line.dot(p.homogeneous())) <= support_distance) support.push_back(p);
  }
  if (!FitLineLeastDistance(support, &line)) return false;
  if (line.y() < 0) line = -line;  // MergedLine's convention: the normal points down.
  JunctionLine& junction = candidate->junction;
  junction.line = line;
  SetSupport(std::move(support), step_px, &junction);
  MergedLine& merged = candidate->merged;
  merged.line = line;
  const Eigen::Vector2d ends[2] = {junction.near_end, junction.far_end};
  SetExtentAlongLine(ends, 2, &merged);
  merged.covered = junction.support_length;
  return true;
}

// Where the band around `previous` lies: its extent lengthened by extend_fraction at each end,
// below roi_top. False when less than 8 px of it is left.
bool BandExtent(const Eigen::Vector3d& line, const JunctionLine& previous, double roi_top,
                double extend_fraction, double* t0, double* t1) {
  *t0 = PositionAlong(line, previous.near_end);
  *t1 = PositionAlong(line, previous.far_end);
  if (*t0 > *t1) std::swap(*t0, *t1);
  const double extension = extend_fraction * (*t1 - *t0);
  *t0 -= extension;
  *t1 += extension;
  const Eigen::Vector2d direction(line.y(), -line.x());
  const Eigen::Vector2d origin = -line.z() * line.head<2>();
  if (std::abs(direction.y()) > 1e-9) {
    const double t_top = (roi_top - origin.y()) / direction.y();
    if (direction.y() > 0) {
      *t0 = std::max(*t0, t_top);
    } else {
      *t1 = std::min(*t1, t_top);
    }
  } else if (origin.y() < roi_top) {
    *t1 = *t0;
  }
  return *t1 - *t0 >= 8;
}

// The candidates in the band around `previous` that the detector's limits allow on its side
// (`left`: rising to the right).
std::vector<TrackedCandidate> BandCandidates(const cv::Mat& bgr, const JunctionLine& previous,
                                             bool left, double roi_top, int step,
                                             const JunctionDetectorOptions& detector,
                                             const JunctionTrackerOptions& options) {
  std::vector<TrackedCandidate> candidates;
  const Eigen::Vector3d& line = previous.line;
  double t0, t1;
  if (!BandExtent(line, previous, roi_top, options.extend_fraction, &t0, &t1)) return candidates;
  const int reach = std::max(4, static_cast<int>(std::lround(options.reach_fraction * bgr.rows)));
  EdgePeakSearch search;
  search.reach_px = reach;
  search.threshold = options.threshold;
  search.step_px = step * options.sample_step;
  search.nearest_only = false;
  Band band;
  band.searched = EdgePeaksAlong(bgr, line, t0, t1, search, &band.peaks);
  const bool by_rows = CrossedByRows(line);
  const Eigen::Vector2d direction(line.y(), -line.x());
  const Eigen::Vector2d origin = -line.z() * line.head<2>();
  const Eigen::Vector2d a = origin + t0 * direction, b = origin + t1 * direction;
  band.first = by_rows ? std::min(a.y(), b.y()) : std::min(a.x(), b.x());
  band.last = by_rows ? std::max(a.y(), b.y()) : std::max(a.x(), b.x());
  const int min_votes =
      std::max(8, static_cast<int>(std::ceil(options.min_support * band.searched)));
  const double diagonal = std::hypot(bgr.cols, bgr.rows);
  const double min_length = detector.min_length_fraction * bgr.rows;
  const double max_length =
      detector.max_length_fraction > 0 ? detector.max_length_fraction * diagonal : 1e300;
  const double max_inclination =
      detector.max_inclination_deg >= 0
          ? detector.max_inclination_deg
          : 90.0 - std::atan2(bgr.rows, bgr.cols) * 180.0 / M_PI;
  const auto voted = VoteForLines(band, reach, min_votes, options.max_lines_per_band);
  for (const BandLine& band_line : voted) {
    std::vector<Eigen::Vector2d> points;
    for (const EdgePeak& peak : band.peaks) {
      const double expected = band_line.offset + band_line.slope * (peak.major - band.middle());
      if (std::abs(peak.offset - expected) <= 2.0) points.push_back(peak.point);
    }
    TrackedCandidate candidate;
    if (!FitCandidate(points, options.support_distance_px, search.step_px, &candidate)) continue;
    const MergedLine& m = candidate.merged;
    if (m.length < min_length || m.length > max_length) continue;
    if (m.inclination_deg < detector.min_inclination_deg || m.inclination_deg > max_inclination) {
      continue;
    }
    if ((m.slope < 0) != left) continue;
    candidate.distance = 0.5 * (std::abs(band_line.offset - band_line.slope * band.half()) +
                                std::abs(band_line.offset + band_line.slope * band.half()));
    candidates.push_back(std::move(candidate));
  }
  return candidates;
}

}  // namespace

bool JunctionTrackerOptions::Check(std::string* why) const {
  std::string reason;
  if (!(reach_fraction > 0 && reach_fraction <= 0.25)) {
    reason = "reach_fraction must be in (0, 0.25]";
  } else if (!(threshold > 0)) {
    reason = "threshold must be positive";
  } else if (!(min_support > 0 && min_support <= 1)) {
    reason = "min_support must be in (0, 1]";
  } else if (!(max_shift_fraction >= 0)) {
    reason = "max_shift_fraction must not be negative";
  } else if (sample_step < 1) {
    reason = "sample_step must be at least 1";
  } else if (max_lines_per_band < 1) {
    reason = "max_lines_per_band must be at least 1";
  } else if (!(extend_fraction >= 0 && extend_fraction <= 1)) {
    reason = "extend_fraction must be in [0, 1]";
  } else if (!(support_distance_px > 0)) {
    reason = "support_distance_px must be positive";
  } else if (redetect_interval < 0) {
    reason = "redetect_interval must not be negative";
  } else if (!(agreement_px > 0)) {
    reason = "agreement_px must be positive";
  } else if (!(min_line_confidence >= 0 && min_line_confidence <= 1)) {
    reason = "min_line_confidence must be in [0, 1]";
  }
  if (why != nullptr) *why = reason;
  return reason.empty();
}

bool TrackJunctions(const cv::Mat& bgr, const JunctionPair& previous,
                    const JunctionDetectorOptions& detector, const JunctionTrackerOptions& options,
                    JunctionPair* tracked, std::string* why) {
  const auto fail = [&](const std::string& what) {
    if (why != nullptr) *why = what;
    return false;
  };
  if (bgr.empty() || bgr.type() != CV_8UC3) return fail("the image is not 8-bit BGR");
  if (!previous.status.ok()) return fail("the previous frame has no junction pair");
  // Where a junction has a lower parallel line (a baseboard's top above the junction, or a
  // recess's floor line), the ceiling check decides between the two on the whole search's lines:
  // a band reaches too little below a junction to see the line below it whole.
  if (previous.has_left_lower || previous.has_right_lower) {
    return fail("the previous junctions have a lower alternative");
  }
  const int height = bgr.rows;
  const int roi_top = std::clamp(static_cast<int>(detector.roi_top_fraction * height), 0,
                                 std::max(0, height - 12));
  const int scale = WorkingScale(bgr.cols, detector.max_work_width);
  std::vector<TrackedCandidate> sides[2];
  for (int s = 0; s < 2; ++s) {
    const bool left = s == 0;
    sides[s] = BandCandidates(bgr, left ? previous.left : previous.right, left, roi_top, scale,
                              detector, options);
    if (sides[s].empty()) {
      return fail(std::string("no line near the previous ") + (left ? "left" : "right") +
                  " junction");
    }
  }
  // The detector's choice among the candidates.
  const cv::Mat roi = bgr.rowRange(roi_top, height);
  const FloorAppearance floor = SampleFloor(roi, roi_top, 2 * scale);
  std::vector<JunctionCandidate> judged[2];
  std::vector<MergedLine> all_lines;
  for (int s = 0; s < 2; ++s) {
    for (const TrackedCandidate& c : sides[s]) {
      judged[s].push_back({c.merged, BoundaryScore(roi, floor, c.merged, roi_top, scale)});
      all_lines.push_back(c.merged);
    }
  }
  BaseboardBandTest band;
  if (detector.baseboard_band_contrast > 0) {
    band.min_contrast = detector.baseboard_band_contrast;
    band.contrast = [&](const MergedLine& upper, const MergedLine& lower) {
      return BandContrast(roi, floor, upper, lower, roi_top, scale);
    };
  }
  const SelectedPair pair = SelectJunctionPair(&judged[0], &judged[1], all_lines,
                                               Eigen::Vector2d(bgr.cols, height), band);
  if (pair.left < 0) {
    return fail(
        "no pair of lines near the previous junctions meets at a vanishing point above "
        "the floor");
  }
  if (pair.left_lower >= 0 || pair.right_lower >= 0) {
    return fail("a junction near the previous one has a lower alternative");
  }
  // The junctions must be the lines nearest the previous ones: a choice of another line in a band
  // (the previous one lost, or judged worse now) is left to the whole search.
  for (int s = 0; s < 2; ++s) {
    const int chosen = s == 0 ? pair.left : pair.right;
    if (sides[s][chosen].distance > options.max_shift_fraction * height) {
      return fail(std::string("the ") + (s == 0 ? "left" : "right") +
                  " junction moved too far from the previous one");
    }
    for (const TrackedCandidate& c : sides[s]) {
      if (c.distance < sides[s][chosen].distance) {
        return fail(std::string("the ") + (s == 0 ? "left" : "right") +
                    " junction is not the line nearest the previous one");
      }
    }
  }
  const auto junction = [&](int s, int index) {
    JunctionLine line = sides[s][index].junction;
    line.confidence = std::clamp(judged[s][index].boundary, 0.0, 1.0) *
                      std::min(1.0, line.support_length / (0.25 * height));
    return line;
  };
  JunctionPair result;
  result.left = junction(0, pair.left);
  result.right = junction(1, pair.right);
  const Eigen::Vector3d vp = result.left.line.cross(result.right.line);
  result.vanishing_point =
      std::abs(vp.z()) > 1e-12 ? Eigen::Vector2d(vp.head<2>() / vp.z()) : pair.vanishing_point;
  // Only the support on the floor's side of the vanishing point counts, as in the detector.
  const auto floor_side = [&](JunctionLine* line, bool left) {
    std::vector<Eigen::Vector2d> kept = FloorSidePixels(line->support, result.vanishing_point, left);
    if (kept.size() < 8) return false;
    if (kept.size() < line->support.size()) {
      SetSupport(std::move(kept), scale * options.sample_step, line);
    }
    return true;
  };
  if (!floor_side(&result.left, true) || !floor_side(&result.right, false)) {
    return fail("a junction near the previous one lies beyond the vanishing point");
  }
  if (result.has_left_lower) result.has_left_lower = floor_side(&result.left_lower, true);
  if (result.has_right_lower) result.has_right_lower = floor_side(&result.right_lower, false);
  // A weak line near the previous one may be a remnant of it (a faded stretch, a shadow) while the
  // junction is elsewhere: a sequence never lets such a line stand for the frame's own search.
  for (const JunctionLine* line : {&result.left, &result.right}) {
    if (line->confidence < options.min_line_confidence) {
      return fail(std::string("the ") + (line == &result.left ? "left" : "right") +
                  " junction near the previous one is weak");
    }
  }
  result.status = Status::Ok();
  *tracked = std::move(result);
  return true;
}

bool SameJunctions(const JunctionPair& a, const JunctionPair& b, double tolerance_px) {
  if (!a.status.ok() || !b.status.ok()) return false;
  const auto same = [&](const JunctionLine& x, const JunctionLine& y) {
    return std::abs(x.line.dot(y.near_end.homogeneous())) <= tolerance_px &&
           std::abs(x.line.dot(y.far_end.homogeneous())) <= tolerance_px;
  };
  return same(a.left, b.left) && same(a.right, b.right);
}

void JunctionTrack::Keep(const JunctionPair& junctions, const cv::Size& size) {
  has_previous_ = junctions.status.ok();
  if (!has_previous_) return;
  size_ = size;
  previous_ = junctions;
  previous_.segments.clear();  // Not needed to track; may be long.
}

void JunctionTrack::Tracked(const JunctionPair& junctions, const cv::Size& size) {
  Keep(junctions, size);
  ++tracked_in_a_row_;
}

void JunctionTrack::Searched(const JunctionPair& junctions, const cv::Size& size, bool agrees) {
  Keep(junctions, size);
  agreed_ = has_previous_ && agrees;
  tracked_in_a_row_ = 0;
}

}  // namespace corridor
