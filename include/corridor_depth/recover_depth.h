#pragma once

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/rasterizer.h"
#include "corridor_depth/solver.h"
#include "corridor_depth/stage_options.h"
#include "corridor_depth/stage_results.h"
#include "corridor_depth/status.h"

namespace corridor {

struct FrameHandover;  // Detect's hand-over to Reconstruct (internal).
class JunctionTrack;   // A sequence's junction track (internal; DepthSequence owns one).

// Everything RecoverDepth can be told. The defaults just work on a calibrated corridor image.
struct RecoverDepthOptions {
  std::string solver = "joint";                // Solver name or chain (grid, closed_form, lm, joint, ...).
  std::string rasterizer = "exact";            // Rasteriser name: exact or paper.
  JunctionDetectorOptions perception;          // Junction-line detection (paper III-A).
  bool track_junctions = true;                 // In a sequence (Detect given a JunctionTrack), seek each junction near the previous frame's first.
  JunctionTrackerOptions tracker;              // That tracking's options.
  SolverOptions solver_options;                // Options of every solver.
  RasterizerOptions rasterizer_options;        // Options of every rasteriser.
  int points_per_line = 30;                    // N: points sampled along each junction (paper III-B).
  bool level_roll = true;                      // Estimate the camera's roll about its optical axis from the walls' vertical edges and, when the evidence is clear, recover the frame turned level (result->roll); the depth is turned back.
  std::string solver_evidence = "edges";       // What the solver named by `solver` fits (chosen_solve.h): "edges", each junction's measured sub-pixel edge points with weights (a side with fewer than points_per_line of them falls back to its line's points); "lines", points_per_line points on each fitted junction line.
  double min_width = 0.5;                      // Narrower estimates are refused (kImplausibleGeometry), m.
  double max_width = 5.0;                      // Wider estimates are refused, m: wider than the corridors the box model is for (a hall), or a line on a wall (a rail, a wainscot's top) taken for the floor's edge.
  double max_abs_yaw = 1.2;                    // |yaw| above this is implausible, rad (~69 deg).
  double max_abs_pitch = 0.8;                  // |pitch| above this is implausible, rad (~46 deg).
  double max_line_error = 0.01;                // RMS distance of the junction points to the lines the
                                               // estimate predicts, over the image diagonal; more is
                                               // implausible (e.g. a solver stopped at a bound).
  double ceiling_height = 0.0;                 // Known ceiling height above the floor, m (0 = estimate or none).
  bool estimate_ceiling = true;                // Without a known height, look for the ceiling/wall junctions.
  CeilingDetectorOptions ceiling;              // Ceiling-height search (beyond the paper).
  bool ceiling_checks_baseboards = true;       // Where a baseboard gave two parallel lines and the upper one was taken, take the lower one when it makes both ceiling junctions agree.
  bool ceiling_checks_inner_lines = true;      // Where a line inside the floor (grout, a box's edge) was taken for a junction, move that wall out to where its ceiling junction agrees with the other side's.
  InnerLineCheckOptions inner_line;            // That check's thresholds.
  BaseboardFeetOptions baseboard_feet;         // Walls on their baseboards' tops (ceiling_checks_baseboards): the bands' feet, at one baseboard height on both walls or at the ceiling sides' ratio on one.
  double width_prior = 0.0;                    // Width for frames where one junction is hidden, m (0 = none; a sequence uses the previous frame's).
  double max_width_change = 0.15;              // In a sequence, a width this much (relative) narrower than the recent frames' (median of the last 5 measured) means one junction is
                                               // wrong (a box edge or grout line taken for it): that width is held from one wall (0 = off), after the ceiling's
                                               // checks, unless the frame's two ceiling junctions agree within 6% (its walls confirmed); a frame whose own
                                               // evidence is not in doubt is held only on its ceiling's word, never over a strong line (pipeline/sequence_holds.h).
  double max_ceiling_disagreement = 0.10;      // In a sequence, a ceiling not found, or whose two sides' heights above the camera differ by more than this
                                               // (|log ratio|; a wall distance is wrong), is replaced by the previous frame's height (0 = off).
  double max_ceiling_change = 0.25;            // In a sequence, a ceiling whose two sides agree but whose height above the camera is more than this
                                               // (relative) off the last trusted one, with the width off by the same factor, means both walls are wrong
                                               // by it (boxes' edges taken on both sides): both are scaled to the trusted ceiling (0 = off).
  bool estimate_end_wall = true;               // Look for a wall across the corridor where both junctions end.
  EndWallDetectorOptions end_wall;             // End-wall search (beyond the paper).
  double min_confidence = 0.6;                 // Frames whose confidence (RecoverDepthResult::confidence) is lower are refused (kLowConfidence); 0 = never. Chosen on generated sets (docs/results.md).
  VerticalCrossingOptions vertical_crossings;  // The confidence's count of vertical edges crossing the junctions.
  CeilingSplitOptions ceiling_split;           // The confidence's test of two ceiling sides that no one height explains.
  int search_max_width = 640;                  // Wider images are halved (pyrDown) until they fit, one copy shared by the ceiling and end-wall searches, px (0 = full resolution).

  bool Check(std::string* why) const;
};

// Wall time of each stage, seconds.
struct StageTimes {
  double perception = 0;  // Junction-line detection.
  double solve = 0;       // Geometry estimation.
  double ceiling = 0;     // Ceiling-height search.
  double end_wall = 0;    // End-wall search.
  double rasterize = 0;   // Dense depth.
  double total = 0;       // The whole call.
};

struct RecoverDepthResult {
  Status status;                   // ok, or why this frame has no depth.
  bool has_geometry = false;       // True once a plausible geometry was estimated.
  CorridorGeometry geometry;       // The estimate (valid when has_geometry).
  JunctionPair junctions;          // Both junction lines (raw pixels), as detected.
  SolverSummary solver_summary;    // What the solver reported.
  CeilingEstimate ceiling;         // The ceiling search (found = false when not run or not seen).
  EndWallEstimate end_wall;        // The end-wall search (found = false when not run or not seen).
  std::string fallback;            // Non-empty when the geometry is not the two junction lines' alone: how
                                   // (one junction and a known width, or the previous frame's width held).
  bool width_held = false;         // True when the recent frames' width replaced this frame's (max_width_change).
  bool width_kept = false;         // True when a much narrower width was kept against the hold (the frame's own evidence strong); a sequence does not take it as a recent width.
  bool walls_scaled = false;       // True when both walls were scaled to the previous trusted ceiling (max_ceiling_change).
  bool ceiling_held = false;       // True when the previous frame's ceiling height replaced this frame's (max_ceiling_disagreement).
  bool ceiling_kept = false;       // True when the frame kept its own ceiling, its sides too weak to compare, against the previous frame's (its own evidence strong); a sequence then holds no ceiling while the two are far apart.
  bool junctions_tracked = false;  // True when the junctions were found near the previous frame's (TrackJunctions), not by a whole search.
  bool ceiling_trusted = false;    // True when the ceiling search found the ceiling and both sides, strong enough to compare, agreed within max_ceiling_disagreement.
  double confidence = 0;           // In [0, 1]: the evidence for the recovered layout (frame_confidence.h); 0 without one.
                                   // Not the per-pixel model-fit mask of confidence_mask.h.
  FrameEvidence evidence;          // What the confidence was computed from.
  int moved_side = -1;             // The wall the inner-line check moved out (0 left, 1 right; -1 none).
  bool lower_line_taken = false;   // True when the baseboard check took a lower parallel line (ceiling_checks_baseboards).
  double roll = 0;                 // The roll the frame was recovered level from (level_roll), rad; 0 when not turned.

  // After Detect: both junctions were found, or only one (Reconstruct may then use a known width).
  bool ReadyToReconstruct() const {
    return status.ok() || (junctions.has_single && status.code() == StatusCode::kNoCorridorFound);
  }
  // Adds how the geometry came about to `fallback` ("; " between notes).
  void AddNote(const std::string& how) { fallback += (fallback.empty() ? "" : "; ") + how; }
  Camera camera;     // The frame's camera (the intrinsics the frame was recovered with).
  cv::Mat depth;     // CV_32F metres, camera-frame z, NaN = no estimate.
  StageTimes times;  // Per-stage wall time.
  // What Detect hands to Reconstruct (the frame as BGR, its search image): internal state, not an
  // output (pipeline/frame_handover.h).
  std::shared_ptr<const FrameHandover> handover;
};

// Recovers depth frame after frame with one solver and one rasteriser, created once.
// Thread-safe: Recover may be called concurrently.
class DepthRecoverer {
 public:
  // Checks the options and creates the solver and rasteriser; InvalidArgument on a bad option
  // or an unknown name (with the valid names).
  static Status Create(const RecoverDepthOptions& options,
                       std::unique_ptr<DepthRecoverer>* recoverer);

  // One frame: 8- or 16-bit, grey, grey+alpha, BGR or BGRA, of the camera's size. The camera
  // must hold a positive mount height. Returns result->status.
  // Equivalent to Detect (with `track`) followed, when it succeeds, by Reconstruct (with
  // `previous`); both may be null, see there.
  Status Recover(const cv::Mat& image, const Camera& camera, RecoverDepthResult* result,
                 const CorridorGeometry* previous = nullptr, JunctionTrack* track = nullptr) const;

  // The two halves of Recover, for the paper's two-thread pipeline: Detect checks the inputs and
  // finds the junction lines (the edge-extraction thread); Reconstruct estimates the geometry
  // and rasterises the depth (the depth-recovery thread). Both return result->status.
  // `track` (may be null) is the sequence's junction track: with track_junctions, the junctions
  // are first sought near its previous frame's (result->junctions_tracked), and the whole search
  // region is searched only when they are lost; the frame's junctions are recorded in it.
  Status Detect(const cv::Mat& image, const Camera& camera, RecoverDepthResult* result,
                JunctionTrack* track = nullptr) const;
  // `previous` (may be null) is the previous frame's geometry in a sequence: when one junction is
  // hidden, its width (and, without a vanishing point, its pitch) stands in; when the two
  // junctions give a much narrower width (max_width_change) that the ceiling's checks leave
  // narrow and the frame's own ceiling does not confirm, it is held (result->width_held).
  Status Reconstruct(const Camera& camera, RecoverDepthResult* result,
                     const CorridorGeometry* previous = nullptr) const;

  const RecoverDepthOptions& options() const { return options_; }

 private:
  DepthRecoverer(const RecoverDepthOptions& options, std::unique_ptr<CorridorSolver> solver,
                 std::unique_ptr<CorridorSolver> layout_solver,
                 std::unique_ptr<DepthRasterizer> rasterizer);

  // The frame's layout (its junctions, checks, holds, end wall and confidence) with the layout's
  // solver, without depth: as seen, then with a wall's own junction further out when refused for
  // the floor going on across a junction. Every decision between layouts is made on this.
  Status ReconstructLayout(const Camera& camera, RecoverDepthResult* result,
                           const CorridorGeometry* previous) const;
  // A recovered layout finished: the options' own solver estimates yaw, pitch, width and offset
  // from its junctions (chosen_solve.h), then the depth is rasterised.
  Status FinishLayout(const Camera& camera, RecoverDepthResult* result) const;
  // The layout as seen, without the roll's levelling.
  Status ReconstructAsSeen(const Camera& camera, RecoverDepthResult* result,
                           const CorridorGeometry* previous) const;
  // After a refusal because the floor goes on across a junction: the frame again with the wall's
  // own junction further out in that line's place (pipeline/outer_junction.h), taken when it is
  // recovered. `detect_notes` are Detect's notes on the frame.
  Status TryOuterJunctions(const Camera& camera, const std::string& detect_notes,
                           RecoverDepthResult* result, const CorridorGeometry* previous) const;

  // LevelRoll decides on the level frame's layout, then finishes it.
  friend bool LevelRoll(const DepthRecoverer& level, const Camera& camera,
                        const CorridorGeometry* previous, RecoverDepthResult* result);

  const RecoverDepthOptions options_;
  const std::unique_ptr<CorridorSolver> solver_;
  // The layout's options and solver (pipeline/chosen_solve.h): the wall checks decide with them,
  // and solver_ estimates the final geometry from the junctions they leave.
  const RecoverDepthOptions layout_options_;
  const std::unique_ptr<CorridorSolver> layout_solver_;
  const std::unique_ptr<DepthRasterizer> rasterizer_;
  // With level_roll: the same options without it, which recovers a frame turned level.
  std::unique_ptr<DepthRecoverer> level_;
};

// One-shot convenience: image + camera -> depth. Returns result->status.
Status RecoverDepth(const cv::Mat& image, const Camera& camera, const RecoverDepthOptions& options,
                    RecoverDepthResult* result);

}  // namespace corridor
