#include "pipeline/frame_confidence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "pipeline/ceiling_agreement.h"
#include "pipeline/floor_beyond_junction.h"

namespace corridor {
namespace {

// Points (search pixels) a floor-beyond measure needs to count, and the fractions of the line with
// the floor on both sides over which its factor falls from 1 to 0.5.
constexpr int kMinFloorBeyondSamples = 20;
constexpr double kFloorBeyondFrom = 0.1, kFloorBeyondTo = 0.2;
// A junction line's confidence below which its little edge support weighs against the layout.
constexpr double kWeakJunctionFrom = 0.03, kWeakJunctionTo = 0.15;
// The factor of a junction line with less than kWeakJunctionFrom, unconfirmed: under the default
// min_confidence (0.6) on its own.
constexpr double kNoJunctionFactor = 0.5;

double Ramp(double x, double x0, double x1) { return std::clamp((x - x0) / (x1 - x0), 0.0, 1.0); }

std::string Format(const char* format, double value) {
  char text[200];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

}  // namespace

double FrameConfidence(const FrameEvidence& e, std::string* why) {
  double confidence = 1.0;
  double weakest = 1.0;
  // The weakest factor's reason, written only when the caller asks and only for a factor that is
  // the weakest so far (most frames' factors are near 1: no strings made for them).
  const char* reason_text = "the evidence is good";
  std::string reason;
  const auto factor = [&](double f, const auto& because) {
    confidence *= f;
    if (f < weakest) {
      weakest = f;
      if (why != nullptr) reason = because(), reason_text = nullptr;
    }
  };
  const char* const side_name[2] = {"left", "right"};
  // Two ceiling sides that agree confirm both walls' distances.
  const bool ceiling_confirms = e.ceiling_disagreement >= 0 &&
                                e.ceiling_disagreement <= std::log(kCeilingSidesAgree);
  for (int s = 0; s < 2; ++s) {
    // A junction line with hardly any boundary evidence or support is a weak base. With none at
    // all (it bounds no floor: a line on a wall, a sill's or a wainscot's) and no ceiling to
    // confirm its wall, the layout rests on nothing: refused on its own.
    if (e.junction[s] >= 0) {
      const double f = e.junction[s] >= kWeakJunctionFrom || ceiling_confirms
                           ? 0.6 + 0.4 * Ramp(e.junction[s], kWeakJunctionFrom, kWeakJunctionTo)
                           : kNoJunctionFactor;
      factor(f, [&] {
        return std::string("the ") + side_name[s] + " junction line has little edge support (" +
               Format("%.2f", e.junction[s]) + ")" +
               (f == kNoJunctionFactor ? " and no ceiling confirms its wall" : "");
      });
    }
    // Vertical edges that go on below a junction: the wall goes on below it. With few edges the
    // fraction is uncertain: it is taken as crossing / (reaching + 1).
    const VerticalCrossings& c = e.crossings[s];
    if (c.reaching >= 3) {
      const double fraction = static_cast<double>(c.crossing) / (c.reaching + 1);
      factor(1.0 - 0.8 * Ramp(fraction, 0.35, 0.75), [&] {
        return std::string("vertical edges cross the ") + side_name[s] + " junction (" +
               std::to_string(c.crossing) + " of " + std::to_string(c.reaching) +
               "): the wall goes on below it (a rail, sill or bench edge taken for the floor's "
               "edge?)";
      });
    }
  }
  // The floor goes on across a junction where its edge support is missing: an object's front foot
  // (a box's, a bench's, a pillar's) taken for the wall's, which ends where the object ends. Two
  // ceiling sides that agree confirm the walls; otherwise the frame cannot tell the object's face
  // from the wall, and the layout that puts the wall on the object may be the wrong one.
  for (int s = 0; s < 2 && !ceiling_confirms; ++s) {
    if (e.floor_across[s] < 0) continue;
    factor(1.0 - 0.5 * Ramp(e.floor_across[s], kFloorBeyondFrom, kFloorBeyondTo), [&] {
      return std::string("the floor goes on across the ") + side_name[s] + " junction on " +
             Format("%.0f%%", 100 * e.floor_across[s]) +
             " of its length: an object's front foot taken for the wall's?";
    });
  }
  // A wall moved out by the ceiling's evidence stands on that evidence alone: its junction is
  // often hidden (by the boxes whose edge was taken for it), so the image cannot confirm it.
  if (e.moved_side >= 0) {
    factor(0.9, [&] {
      return std::string("the ") + side_name[e.moved_side] +
             " wall was moved out to where its ceiling junction agrees with the other's";
    });
  }
  // Ceiling: two sides that disagree put one wall at a wrong distance, or the ceiling junctions
  // were misread (a window band, a glass wall's room behind, a steep view): it weighs less.
  if (e.ceiling_disagreement >= 0) {
    factor(1.0 - 0.4 * Ramp(e.ceiling_disagreement, 0.1, 0.3), [&] {
      return Format("the two ceiling sides disagree by %.0f%%: a junction is not the floor's edge",
                    100 * (std::exp(e.ceiling_disagreement) - 1));
    });
  }
  // Two ceiling sides no one height explains, with a line where a wall would agree with them: two
  // layouts fit the image's lines (a baseboard's top or a rail on one wall, a runner's edge on the
  // floor), and this one may be the wrong one. Refused on its own.
  if (e.ceiling_split >= 0) {
    factor(0.5, [&] {
      return Format("the two ceiling sides are %.0f%% apart", 100 * (std::exp(e.ceiling_split) - 1)) +
             ", no one ceiling fits both, and a junction where a wall would agree with them "
             "follows edges: two layouts fit (a baseboard's top, a rail or a runner's edge taken "
             "for the floor's edge?)";
    });
  }
  if (e.corrected) {
    factor(0.9, [] {
      return std::string(
          "the geometry needed a correction (one junction, a held width or a lower line)");
    });
  }
  if (why != nullptr) {
    if (reason_text != nullptr) {
      *why = reason_text;
    } else {
      *why = std::move(reason);
    }
  }
  return std::clamp(confidence, 0.0, 1.0);
}

bool FloorGoesOnAcross(const FrameEvidence& evidence, int s) {
  return (s == 0 || s == 1) && evidence.floor_across[s] >= kFloorBeyondFrom;
}

bool JunctionFullySupported(const FrameEvidence& evidence, int s) {
  return (s == 0 || s == 1) && evidence.junction[s] >= kWeakJunctionTo;
}

FrameEvidence GatherFrameEvidence(const JunctionPair& junctions, const WorkingImage& search,
                                  const CorridorGeometry& geometry, double ceiling_disagreement,
                                  bool corrected, int moved_side,
                                  const VerticalCrossingOptions& options,
                                  double ceiling_split) {
  FrameEvidence evidence;
  const JunctionLine* lines[2] = {nullptr, nullptr};
  if (junctions.status.ok()) {
    lines[0] = &junctions.left, lines[1] = &junctions.right;
  } else if (junctions.has_single) {
    lines[junctions.single_is_left ? 0 : 1] = &junctions.single;
  }
  for (int s = 0; s < 2; ++s) {
    if (lines[s] == nullptr) continue;
    evidence.junction[s] = lines[s]->confidence;
    if (!search.bgr.empty()) {
      evidence.crossings[s] = CountVerticalCrossings(search.bgr, search.camera, search.scale,
                                                     geometry, *lines[s], options);
    }
  }
  if (junctions.status.ok() && !search.bgr.empty()) {
    for (int s = 0; s < 2; ++s) {
      // A moved wall no longer stands on its detected line.
      if (s == moved_side) continue;
      const FloorBeyond beyond = MeasureFloorBeyond(search, geometry, *lines[s],
                                                    *lines[1 - s], junctions.vanishing_point);
      if (beyond.samples >= kMinFloorBeyondSamples) evidence.floor_across[s] = beyond.floor_across;
    }
  }
  evidence.ceiling_disagreement = ceiling_disagreement;
  evidence.corrected = corrected;
  evidence.moved_side = moved_side;
  evidence.ceiling_split = ceiling_split;
  return evidence;
}

}  // namespace corridor
