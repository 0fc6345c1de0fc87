#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "perception/junction_detector.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/stage_options.h"

namespace corridor {

// Finds the two junctions of `bgr` (8-bit, 3 channels) near `previous`'s (found in the previous
// frame, of the same size). In a band around each previous line, the edge points (colour gradient
// peaks across the line, on every sample_step-th row or column of the working scale along its
// extent) vote for the lines they support;
// the best supported become candidates, fitted to their points. The detector's own choice
// (SelectJunctionPair, with its boundary scores and baseboard rule) then picks the pair among
// them, so that a baseboard's top or a door's foot in a band is judged as in a whole search. The
// detector's options give the search region's top, the length and inclination limits and the
// working scale (the row step). A pair with a lower alternative on either side (a baseboard's top
// or a recess's floor line above the junction), in `previous` or among the candidates, is left to
// the whole search, whose ceiling check decides between the two: a band reaches too little below
// a junction to see the line below it whole.
// True and *tracked filled (status ok, floor texture not measured, no segments) when a pair is
// found; false, *tracked untouched and *why set otherwise: the caller searches the whole region.
bool TrackJunctions(const cv::Mat& bgr, const JunctionPair& previous,
                    const JunctionDetectorOptions& detector, const JunctionTrackerOptions& options,
                    JunctionPair* tracked, std::string* why);

// True when both junctions of `a` and `b` are the same lines: each of a's lines passes within
// `tolerance_px` of both ends of b's.
bool SameJunctions(const JunctionPair& a, const JunctionPair& b, double tolerance_px);

// What a sequence's junction search carries from frame to frame: the last frame's junctions, and
// whether a tracked pair may stand for a frame. A pair tracked from a wrong pair is as wrong, so
// tracking is trusted only once a whole search found the lines it tracked to (the search of a
// frame agreed with the pair tracked into it) and that frame's walls were not left unconfirmed
// (Unconfirmed), and for redetect_interval frames after that; then
// the next frame is searched whole again, and checked against its tracked pair. The interval is
// the recoverer's option (JunctionTrackerOptions::redetect_interval), passed where it is asked.
class JunctionTrack {
 public:
  // The previous frame's junctions when that frame was of `size`; null otherwise (or none).
  const JunctionPair* Previous(const cv::Size& size) const {
    return has_previous_ && size == size_ ? &previous_ : nullptr;
  }

  // True when a pair tracked into the next frame may stand for it (see the class comment), after
  // at most `redetect_interval` tracked frames in a row (0 = any number).
  bool Trusted(int redetect_interval) const {
    return has_previous_ && agreed_ &&
           (redetect_interval == 0 || tracked_in_a_row_ < redetect_interval);
  }

  // Records a frame of `size` whose junctions were tracked.
  void Tracked(const JunctionPair& junctions, const cv::Size& size);

  // Records a frame of `size` searched whole; `agrees`: the pair tracked into it was the one
  // found. A frame without both junctions ends the track.
  void Searched(const JunctionPair& junctions, const cv::Size& size, bool agrees);

  // The last searched frame's walls were not confirmed (its two ceiling sides did not agree, or it
  // was refused): its pair may be the same wrong lines found twice, and is not tracked on.
  void Unconfirmed() { agreed_ = false; }

 private:
  void Keep(const JunctionPair& junctions, const cv::Size& size);

  JunctionPair previous_;
  cv::Size size_;
  bool has_previous_ = false;
  bool agreed_ = false;       // The last whole search agreed with its tracked pair.
  int tracked_in_a_row_ = 0;  // Frames tracked since that search.
};

}  // namespace corridor
