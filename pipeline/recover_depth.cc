#include "corridor_depth/recover_depth.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "kernels/mat_memory.h"
#include "pipeline/ceiling_agreement.h"
#include "pipeline/ceiling_split.h"
#include "pipeline/chosen_solve.h"
#include "pipeline/frame_handover.h"
#include "pipeline/image_input.h"
#include "pipeline/one_junction.h"
#include "pipeline/outer_junction.h"
#include "pipeline/roll_leveling.h"
#include "pipeline/plausibility.h"
#include "pipeline/sequence_holds.h"
#include "pipeline/solver_evidence.h"
#include "pipeline/baseboard_feet.h"
#include "pipeline/wall_checks.h"
#include "perception/end_wall_detector.h"
#include "perception/junction_detector.h"
#include "perception/junction_memory.h"
#include "perception/junction_tracker.h"
#include "pipeline/frame_confidence.h"

namespace corridor {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

DepthRecoverer::DepthRecoverer(const RecoverDepthOptions& options,
                               std::unique_ptr<CorridorSolver> solver,
                               std::unique_ptr<CorridorSolver> layout_solver,
                               std::unique_ptr<DepthRasterizer> rasterizer)
    : options_(options),
      solver_(std::move(solver)),
      layout_options_(LayoutOptions(options)),
      layout_solver_(std::move(layout_solver)),
      rasterizer_(std::move(rasterizer)) {}

Status DepthRecoverer::Create(const RecoverDepthOptions& options,
                              std::unique_ptr<DepthRecoverer>* recoverer) {
  std::string why;
  if (!options.Check(&why)) return Status::InvalidArgument(why);
  BuildOpenCvTablesOnce();
  std::unique_ptr<CorridorSolver> solver;
  Status status = CreateSolver(options.solver, options.solver_options, &solver);
  if (!status.ok()) return status;
  std::unique_ptr<DepthRasterizer> rasterizer;
  status = CreateRasterizer(options.rasterizer, options.rasterizer_options, &rasterizer);
  if (!status.ok()) return status;
  std::unique_ptr<CorridorSolver> layout_solver;
  status = CreateSolver(LayoutSolverName(), options.solver_options, &layout_solver);
  if (!status.ok()) return status;
  recoverer->reset(new DepthRecoverer(options, std::move(solver), std::move(layout_solver),
                                      std::move(rasterizer)));
  if (options.level_roll) {
    RecoverDepthOptions level = options;
    level.level_roll = false;
    status = Create(level, &(*recoverer)->level_);
    if (!status.ok()) return status;
  }
  return Status::Ok();
}

Status DepthRecoverer::Recover(const cv::Mat& image, const Camera& camera,
                               RecoverDepthResult* result, const CorridorGeometry* previous,
                               JunctionTrack* track) const {
  const auto start = Clock::now();
  const auto detect_and_reconstruct = [&](RecoverDepthResult* into, JunctionTrack* with) {
    Detect(image, camera, into, with);
    if (into->ReadyToReconstruct()) Reconstruct(camera, into, previous);
  };
  detect_and_reconstruct(result, track);
  if (track != nullptr && !TrackConfirmedBy(options_, *result)) {
    if (result->junctions_tracked) {
      // Tracked lines the frame's ceiling does not confirm: the frame is searched whole, and the
      // track goes on from that search, unconfirmed.
      detect_and_reconstruct(result, nullptr);
      track->Searched(result->junctions, image.size(), false);
    } else {
      track->Unconfirmed();
    }
  } else if (track != nullptr && result->junctions_tracked && options_.ceiling_height <= 0 &&
             options_.estimate_ceiling) {
    // Tracked lines the ceiling confirms: the frame's own whole search, when it is confirmed
    // too, is kept instead (OwnSearchKept), and the track goes on from it.
    RecoverDepthResult own;
    detect_and_reconstruct(&own, nullptr);
    if (OwnSearchKept(options_, own)) {
      const bool agrees =
          SameJunctions(result->junctions, own.junctions, options_.tracker.agreement_px);
      *result = std::move(own);
      track->Searched(result->junctions, image.size(), agrees);
    }
  }
  result->times.total = SecondsSince(start);
  return result->status;
}

Status DepthRecoverer::Detect(const cv::Mat& image, const Camera& camera,
                              RecoverDepthResult* result, JunctionTrack* track) const {
  const auto start = Clock::now();
  // The previous frame's handover is used again when nothing else holds it (it was made here,
  // not const): one allocation less a frame. So is the memory of its halving, of its depth
  // (handed on to Reconstruct) and of its junctions' vectors (junction_memory.h).
  std::shared_ptr<FrameHandover> handover;
  cv::Mat depth_memory = std::move(result->depth);
  WorkingImage halved;
  if (result->handover != nullptr && result->handover.use_count() == 1) {
    handover = std::const_pointer_cast<FrameHandover>(std::move(result->handover));
    halved.bgr = std::move(handover->search.bgr);
    if (depth_memory.empty()) depth_memory = std::move(handover->depth_memory);
    *handover = FrameHandover();
  }
  ReleaseUnlessSole(&depth_memory);
  RecycleJunctionMemory(&result->junctions);
  *result = RecoverDepthResult();
  const auto finish = [&](Status status) {
    result->status = status;
    result->times.perception = SecondsSince(start);
    result->times.total = result->times.perception;
    return status;
  };
  std::string why;
  if (!camera.Check(&why)) return finish(Status::InvalidArgument("camera: " + why));
  cv::Mat bgr;
  Status status = ToBgr(image, camera, &bgr);
  if (!status.ok()) return finish(status);
  if (handover == nullptr) handover = std::make_shared<FrameHandover>();
  handover->image = bgr;
  handover->depth_memory = std::move(depth_memory);
  result->handover = handover;
  result->camera = camera;
  // In a sequence, the junctions near the previous frame's; they stand for the frame when the
  // track trusts them, else the whole search runs and is checked against them.
  JunctionPair tracked;
  const JunctionPair* previous_junctions =
      track != nullptr && options_.track_junctions ? track->Previous(bgr.size()) : nullptr;
  const bool has_tracked =
      previous_junctions != nullptr && TrackJunctions(bgr, *previous_junctions, options_.perception,
                                                      options_.tracker, &tracked, &why);
  if (has_tracked && track->Trusted(options_.tracker.redetect_interval)) {
    result->junctions = std::move(tracked);
    result->junctions_tracked = true;
    track->Tracked(result->junctions, bgr.size());
    return finish(Status::Ok());
  }
  // When the junction search halves the image and the ceiling/end-wall searches halve it as far or
  // further, one halving of the whole image serves both: the searches' image is halved from it.
  const int junction_scale = WorkingScale(bgr.cols, options_.perception.max_work_width);
  const int search_scale = WorkingScale(bgr.cols, options_.search_max_width);
  if (junction_scale > 1 && search_scale >= junction_scale) {
    HalveToWidth(bgr, camera, options_.perception.max_work_width, nullptr, &halved);
    status = DetectJunctions(bgr, halved.bgr, options_.perception, &result->junctions);
    handover->search = search_scale == junction_scale
                           ? halved
                           : HalveToWidth(halved.bgr, halved.camera, options_.search_max_width);
    handover->search.scale = search_scale;
  } else {
    status = DetectJunctions(bgr, options_.perception, &result->junctions);
  }
  if (result->junctions.status.ok() && result->junctions.relaxed_hough) {
    result->AddNote("junctions from the second, relaxed Hough look: a faint or broken junction");
  }
  if (track != nullptr) {
    track->Searched(result->junctions, bgr.size(),
                    has_tracked && SameJunctions(tracked, result->junctions,
                                                 options_.tracker.agreement_px));
  }
  if (!status.ok()) return finish(status);
  return finish(result->junctions.status);
}

Status DepthRecoverer::Reconstruct(const Camera& camera, RecoverDepthResult* result,
                                   const CorridorGeometry* previous) const {
  const Status status = ReconstructLayout(camera, result, previous);
  // A frame refused for its confidence is tried level too: a roll the model lacks may be what
  // weakens its evidence. A level frame taken is finished there.
  if ((status.ok() || status.code() == StatusCode::kLowConfidence) && level_ != nullptr &&
      LevelRoll(*level_, camera, previous, result)) {
    return result->status;
  }
  return FinishLayout(camera, result);
}

Status DepthRecoverer::ReconstructLayout(const Camera& camera, RecoverDepthResult* result,
                                         const CorridorGeometry* previous) const {
  const std::string detect_notes = result->fallback;
  const Status status = ReconstructAsSeen(camera, result, previous);
  if (status.code() == StatusCode::kLowConfidence) {
    return TryOuterJunctions(camera, detect_notes, result, previous);
  }
  return status;
}

Status DepthRecoverer::FinishLayout(const Camera& camera, RecoverDepthResult* result) const {
  if (!result->status.ok() || !result->has_geometry) return result->status;
  const auto start = Clock::now();
  const auto finish = [&](Status status) {
    result->status = status;
    result->times.total += SecondsSince(start);
    return status;
  };
  // The options' own solver on the layout's junctions, when the frame's walls are theirs: not
  // one hidden, nor a wall the inner-line check moved (the ceiling's, not a junction line's), nor
  // a width held or walls scaled from the previous frames.
  if (ChosenSolveDiffers(options_) && result->junctions.status.ok() && result->moved_side < 0 &&
      !result->width_held && !result->walls_scaled) {
    const Status status = ChosenSolve(*solver_, options_, result->junctions, camera,
                                      &result->geometry, &result->solver_summary);
    result->times.solve += SecondsSince(start);
    if (!status.ok()) {
      result->has_geometry = false;
      return finish(status);
    }
  }
  const auto stage = Clock::now();
  // Into the previous frame's depth memory (Detect's), when the handover is this result's alone;
  // a refusal before the rasteriser wrote into it leaves no depth, as without it.
  if (result->handover != nullptr && result->handover.use_count() == 1) {
    FrameHandover& own = *std::const_pointer_cast<FrameHandover>(result->handover);
    result->depth = std::move(own.depth_memory);
  }
  const uchar* const given = result->depth.datastart;
  Status status = rasterizer_->RenderNoEstimateNaN(result->geometry, camera, &result->depth);
  if (!status.ok() && given != nullptr && result->depth.datastart == given) result->depth.release();
  result->times.rasterize = SecondsSince(stage);
  return finish(status);
}

Status DepthRecoverer::TryOuterJunctions(const Camera& camera, const std::string& detect_notes,
                                         RecoverDepthResult* result,
                                         const CorridorGeometry* previous) const {
  if (!result->junctions.status.ok() || result->handover == nullptr ||
      result->handover->image.empty()) {
    return result->status;
  }
  // Only a refusal that the floor across a junction decides: that evidence alone refuses the
  // frame.
  const FrameEvidence& evidence = result->evidence;
  FrameEvidence floor_only;
  floor_only.floor_across[0] = evidence.floor_across[0];
  floor_only.floor_across[1] = evidence.floor_across[1];
  if (FrameConfidence(floor_only) >= options_.min_confidence) return result->status;
  // The side the floor goes on across more first.
  const int first = evidence.floor_across[1] > evidence.floor_across[0] ? 1 : 0;
  for (const int s : {first, 1 - first}) {
    JunctionLine outer;
    if (!FloorGoesOnAcross(evidence, s) ||
        !FindOuterJunction(result->junctions, s, result->handover->image,
                           WorkingScale(result->handover->image.cols,
                                        options_.perception.max_work_width),
                           &outer)) {
      continue;
    }
    RecoverDepthResult trial;
    trial.junctions = result->junctions;
    if (!ReplaceJunction(s, std::move(outer), &trial.junctions)) continue;
    trial.junctions_tracked = result->junctions_tracked;
    trial.camera = result->camera;
    trial.handover = result->handover;
    trial.times.perception = result->times.perception;
    trial.fallback = detect_notes;
    // Taken when recovered, with the new line as well supported as a plain junction, and the
    // floor not going on across it either (whatever the ceiling says: the wall's own junction has
    // the wall beyond it all along).
    if (!ReconstructAsSeen(camera, &trial, previous).ok() ||
        !JunctionFullySupported(trial.evidence, s) || FloorGoesOnAcross(trial.evidence, s)) {
      continue;
    }
    const std::string refusal = result->status.message();
    *result = std::move(trial);
    result->AddNote(std::string("the ") + (s == 0 ? "left" : "right") +
                    " wall's own junction, further out, taken for the line first taken (" +
                    refusal + ")");
    return result->status;
  }
  return result->status;
}

Status DepthRecoverer::ReconstructAsSeen(const Camera& camera, RecoverDepthResult* result,
                                         const CorridorGeometry* previous) const {
  const auto start = Clock::now();
  const auto finish = [&](Status status) {
    result->status = status;
    result->times.total = result->times.perception + SecondsSince(start);
    return status;
  };
  auto stage = Clock::now();
  CorridorGeometry geometry;
  Status status;
  if (!result->junctions.status.ok()) {
    // One junction hidden: with a known width (the previous frame's, else the option) the other
    // wall follows; never a made-up second line. Otherwise the detector's reason stands.
    if (!result->junctions.has_single) return finish(result->junctions.status);
    const double width = previous != nullptr ? previous->width : options_.width_prior;
    status = GeometryFromOneJunction(result->junctions, camera, width, previous, &geometry,
                                     &result->fallback);
    if (previous != nullptr && status.ok()) result->fallback += " (previous frame)";
    result->times.solve = SecondsSince(stage);
    if (!status.ok()) {
      return finish(Status(status.code(), result->junctions.status.message() + "; " +
                                              status.message()));
    }
    status = CheckPlausible(geometry, options_);
    if (!status.ok()) return finish(status);
  } else {
    // The junctions' edge points, when the solvers are to see them (here and in the checks).
    if (result->handover != nullptr) {
      MeasureSolverEvidence(result->handover->image, options_, &result->junctions);
    }
    // The layout's solve (chosen_solve.h); the thread's observation keeps its memory.
    thread_local CorridorObservation thread_observation;
    const CorridorObservation& observation = thread_observation;
    ObservationFromJunctions(result->junctions, camera, layout_options_, &thread_observation);
    status = layout_solver_->Solve(observation, nullptr, &result->solver_summary);
    result->times.solve = SecondsSince(stage);
    if (!status.ok()) {
      if (status.code() == StatusCode::kInvalidArgument) {
        status = Status::NoCorridorFound("junction lines unusable: " + status.message());
      }
      return finish(status);
    }
    geometry = result->solver_summary.estimate;
    geometry.camera_height = camera.mount_height;
    status = CheckPlausibleShape(geometry, layout_options_);
    if (status.ok()) status = CheckLineFit(geometry, observation, camera, layout_options_);
    if (!status.ok()) return finish(status);
  }
  geometry.ceiling_height = options_.ceiling_height;
  stage = Clock::now();
  // The ceiling and end-wall searches share one image at the search resolution.
  const FrameHandover* handover = result->handover.get();
  const bool has_image = handover != nullptr && !handover->image.empty();
  const bool search_ceiling =
      options_.ceiling_height <= 0 && options_.estimate_ceiling && has_image;
  const bool search_end_wall = options_.estimate_end_wall && has_image;
  WorkingImage search;
  if (search_ceiling || search_end_wall) {
    search = handover->search.bgr.empty()
                 ? HalveToWidth(handover->image, camera, options_.search_max_width)
                 : handover->search;
  }
  // The search image's edges, shared by the frame's searches: when the end-wall search reads the
  // image at its own resolution, it needs all of them, computed once here; otherwise the first
  // ceiling search computes the rows it needs, and the checks' searches reuse them.
  ImageEdges edges;
  if (search_end_wall && WorkingScale(search.bgr.cols, options_.end_wall.max_work_width) == 1) {
    ComputeImageEdges(search.bgr, &edges);
  }
  ColourFootMemo colour_feet;
  const WallCheckInputs checks{layout_options_, *layout_solver_, camera, search, &edges,
                               &colour_feet};
  if (search_ceiling) {
    status = SearchCeiling(checks, &geometry, &result->ceiling);
    if (!status.ok()) return finish(status);
    bool lower_taken = false;
    if (options_.ceiling_checks_baseboards && result->junctions.status.ok()) {
      lower_taken = CheckBaseboards(checks, &geometry, result) ||
                    TakeFootOfSplitWall(checks, &geometry, result);
      if (!lower_taken) {
        BaseboardFeet feet =
            TakeBothBaseboardFeet(checks, options_.baseboard_feet, &geometry, result);
        if (!feet.taken) {
          feet = TakeOneBaseboardFoot(checks, options_.baseboard_feet, &geometry, result);
        }
        if (!feet.taken) {
          feet = TakeFootShownAcross(checks, options_.baseboard_feet, &geometry, result);
        }
        if (feet.taken) {
          lower_taken = true;
          status = SearchCeiling(checks, &geometry, &result->ceiling);
          if (!status.ok()) return finish(status);
        }
      }
      result->lower_line_taken = lower_taken;
    }
    // A lower line taken has made the two ceiling sides agree: nothing for the inner-line check.
    if (options_.ceiling_checks_inner_lines && result->junctions.status.ok() && !lower_taken) {
      status = MoveInnerWall(checks, previous, &geometry, result);
      if (!status.ok()) return finish(status);
    }
  }
  // The width hold comes after the checks, which may have moved a wall out with this frame's own
  // evidence. A width still much narrower whose two ceiling junctions, each searched alone, agree
  // (within 6%: what the baseboard check needs no check for) is this frame's walls confirmed: the
  // previous frame's wider width was the wrong one, and holding it would carry the mistake on.
  // (Only a width from two junctions: with one, the previous width is already this frame's.)
  // A frame is doubted when its own confidence (on its own geometry, before any hold) is below
  // min_confidence, its two ceiling sides measurably disagree, or its junctions are the tracker's
  // (found near the previous frame's, not by the frame's own search); only then may a hold that
  // cannot tell the wrong wall from the ceiling overrule it (HoldWidth).
  const CorridorGeometry* hold_from = result->junctions.status.ok() ? previous : nullptr;
  double own_confidence = -1;  // Computed once, when a hold or a scaling is considered.
  // The ceiling's split (ceiling_split.h) of the walls the ceiling estimate was searched for.
  const auto ceiling_split = [&] {
    return search_ceiling ? CeilingSplit(search.bgr, search.camera, geometry, result->ceiling,
                                         options_.ceiling, options_.ceiling_split, &edges)
                          : -1.0;
  };
  const auto own_confidence_low = [&](double disagreement) {
    if (own_confidence < 0) {
      own_confidence = FrameConfidence(GatherFrameEvidence(
          result->junctions, search, geometry, disagreement, result->lower_line_taken,
          result->moved_side, options_.vertical_crossings, ceiling_split()));
    }
    return own_confidence < options_.min_confidence;
  };
  if (hold_from != nullptr && MuchNarrower(*hold_from, options_.max_width_change, geometry)) {
    const double disagreement =
        search_ceiling ? CeilingDisagreement(result->ceiling, geometry.camera_height) : -1;
    if (!(disagreement >= 0 && disagreement <= std::log(kCeilingSidesAgree))) {
      own_confidence_low(disagreement);
      const bool doubted =
          FrameInDoubt(own_confidence, options_.min_confidence, disagreement,
                       std::log(kCeilingSidesAgree), result->junctions_tracked);
      HoldWidth(*hold_from, options_.max_width_change, doubted, &geometry, result);
      if (search_ceiling && result->width_held) {  // The ceiling of the held walls.
        status = SearchCeiling(checks, &geometry, &result->ceiling);
        if (!status.ok()) return finish(status);
      }
    }
  }
  if (search_ceiling) {
    // Whether the frame is in doubt only when a hold is considered: its confidence costs a look.
    // Its ceiling's sides disagreeing are what the hold is about, not a doubt of the frame (they
    // weigh in its confidence).
    bool ceiling_doubted = true;
    if (CeilingHoldConsidered(previous, options_.max_ceiling_disagreement,
                              options_.ceiling.min_support, geometry, result)) {
      const double disagreement = CeilingDisagreement(result->ceiling, geometry.camera_height);
      own_confidence_low(disagreement);
      ceiling_doubted = FrameInDoubt(own_confidence, options_.min_confidence, -1, 0,
                                     result->junctions_tracked);
    }
    HoldCeiling(previous, options_.max_ceiling_disagreement, options_.ceiling.min_support,
                ceiling_doubted, &geometry, result);
    if (hold_from != nullptr &&
        WallScaleFactor(*hold_from, options_.max_ceiling_change, geometry, *result) > 0) {
      const double disagreement = CeilingDisagreement(result->ceiling, geometry.camera_height);
      own_confidence_low(disagreement);
      const bool doubted =
          FrameInDoubt(own_confidence, options_.min_confidence, disagreement,
                       std::log(kCeilingSidesAgree), result->junctions_tracked);
      ScaleWallsToCeiling(*hold_from, options_.max_ceiling_change, doubted, &geometry, result);
    }
  }
  result->times.ceiling = SecondsSince(stage);
  // The width bounds on the layout reported, after the checks and holds that may move its walls.
  status = CheckCorridorWidth(geometry, options_);
  if (!status.ok()) return finish(status);
  stage = Clock::now();
  if (search_end_wall) {
    status =
        DetectEndWall(search.bgr, search.camera, geometry, options_.end_wall, &result->end_wall,
                      &edges);
    if (!status.ok()) return finish(status);
    if (result->end_wall.found) geometry.end_distance = result->end_wall.distance;
  }
  result->times.end_wall = SecondsSince(stage);
  result->geometry = geometry;
  // The frame's confidence, from the evidence for this geometry.
  const JunctionPair& junctions = result->junctions;
  result->evidence = GatherFrameEvidence(
      junctions, search, geometry,
      search_ceiling ? CeilingDisagreement(result->ceiling, geometry.camera_height) : -1,
      !junctions.status.ok() || result->width_held || result->walls_scaled ||
          result->lower_line_taken,
      result->moved_side, options_.vertical_crossings, ceiling_split());
  result->confidence = FrameConfidence(result->evidence);
  NoteRescue(own_confidence, options_.min_confidence, result);
  if (result->confidence < options_.min_confidence) {
    // The weakest factor's reason only for a refusal's message.
    std::string weakest;
    FrameConfidence(result->evidence, &weakest);
    std::ostringstream msg;
    msg.precision(2);
    msg << std::fixed << "confidence " << result->confidence << " is below "
        << options_.min_confidence << ": " << weakest;
    return finish(Status::LowConfidence(msg.str()));
  }
  result->has_geometry = true;
  return finish(Status::Ok());
}

Status RecoverDepth(const cv::Mat& image, const Camera& camera, const RecoverDepthOptions& options,
                    RecoverDepthResult* result) {
  std::unique_ptr<DepthRecoverer> recoverer;
  const Status status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) {
    *result = RecoverDepthResult();
    result->status = status;
    return status;
  }
  return recoverer->Recover(image, camera, result);
}

}  // namespace corridor
