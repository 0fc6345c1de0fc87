#include "tools/tool_flags.h"

DEFINE_string(camera, "",
              "Camera calibration YAML (ROS camera_info + camera_height); overrides "
              "<scene>/camera.yaml and <dataset>/camera.yaml");
DEFINE_double(fx, 0.0, "Uncalibrated mode: focal length x, px (with --fy, --cx, --cy; no file)");
DEFINE_double(fy, 0.0, "Uncalibrated mode: focal length y, px (0 = --fx)");
DEFINE_double(cx, -1.0, "Uncalibrated mode: principal point x, px (< 0 = image centre)");
DEFINE_double(cy, -1.0, "Uncalibrated mode: principal point y, px (< 0 = image centre)");
DEFINE_double(hfov, 0.0,
              "Uncalibrated mode: horizontal field of view, degrees, for images without a "
              "calibration file (principal point at the centre)");
DEFINE_string(focal, "",
              "Uncalibrated mode: 'auto' estimates the focal length from two orthogonal vanishing "
              "points (corridor + door tops, tile grout, light edges or verticals); falls back to "
              "--hfov (else 60 deg) and says so");
DEFINE_double(camera_height, 0.0, "Camera height above the floor, m; overrides the YAML key");
DEFINE_string(solver, "joint",
              "Solver: joint (all four parameters at once), grid (the paper's search), "
              "closed_form, lm, or a chain such as closed_form+lm");
DEFINE_string(rasterizer, "exact", "Depth rasteriser: exact or paper");
DEFINE_double(max_range, 40.0, "Depth beyond this gets no estimate, m");
DEFINE_double(max_height, 2.5, "Without a ceiling, wall points higher than this get no estimate, m");
DEFINE_double(ceiling_height, 0.0, "Known ceiling height above the floor, m (0 = unknown)");
DEFINE_double(width_prior, 0.0,
              "Corridor width for frames where one junction is hidden, m (0 = none; in a sequence "
              "the previous frame's width is used)");
DEFINE_double(max_width_change, 0.15,
              "In a sequence, a width this much (relative) narrower than the recent frames' (the "
              "median of the last 5 measured) means one junction is wrong: that width is held, for "
              "up to 3 frames in a row (0 = off)");
DEFINE_double(max_ceiling_disagreement, 0.10,
              "In a sequence, a frame whose ceiling was not found, or whose two sides' heights "
              "above the camera differ by more than this (|log ratio|), takes the previous "
              "frame's ceiling height (0 = off)");
DEFINE_double(max_ceiling_change, 0.25,
              "In a sequence, a ceiling whose two sides agree but whose height above the camera "
              "is more than this (relative) off the last trusted one, the width off alike, means "
              "both junctions are wrong alike: both walls are scaled to the trusted ceiling "
              "(0 = off)");
DEFINE_bool(end_wall, true,
            "Look for a wall across the corridor where both junctions end, and close the depth "
            "there (beyond the paper)");
DEFINE_bool(inner_line_check, true,
            "Where a line inside the floor (grout, a box's edge) was taken for a junction, move that "
            "wall out to where its ceiling junction agrees with the other side's (beyond the paper)");
DEFINE_double(baseboard_feet_same_ratio, 0.015,
              "Both junctions on baseboards' tops: when the feet of the bands below them move both "
              "walls in by one ratio, within this (relative), giving one baseboard height of "
              "0.03-0.2 m, the feet are the junctions (beyond the paper; 0 = off)");
DEFINE_double(baseboard_feet_ceiling_ratio, 0.03,
              "One junction on a baseboard's top: when the foot of the band below it moves its wall "
              "in by its ceiling side's height over the other's, within this (relative), the foot "
              "is the junction (beyond the paper; 0 = off)");
DEFINE_double(baseboard_feet_across_support, 0.5,
              "One junction on a baseboard's top, the ceiling not telling: when the other wall "
              "shows the band's top at the height its foot gives, on edges over this fraction of "
              "its view, the foot is the junction (beyond the paper; 0 = off)");
DEFINE_int32(search_max_width, 640,
             "Wider images are halved before the ceiling and end-wall searches until they fit, px "
             "(0 = full resolution)");
DEFINE_int32(junction_max_width, 640,
             "Wider images are halved before the junction-line search until they fit, px "
             "(0 = full resolution); the ceiling and end-wall searches reuse its halving of the whole "
             "image when --search_max_width halves as far or further");
DEFINE_double(baseboard_band_contrast, 1.45,
              "A line just below the chosen junction, parallel to it, is the junction instead (the "
              "chosen one a baseboard top) when the band between them is this unlike the floor "
              "below, in floor-texture spreads; raise it for glossy floors that mirror the "
              "baseboard; 0 = off");
DEFINE_bool(track_junctions, true,
            "In a sequence, seek each junction near the previous frame's first, and search the "
            "whole region only when it is lost (and every --redetect_interval frames)");
DEFINE_int32(redetect_interval, 10,
             "With --track_junctions, search the whole region again after this many tracked "
             "frames in a row (0 = never once trusted)");
DEFINE_int32(points_per_line, 30, "Points sampled along each junction line for the solver");
DEFINE_bool(level_roll, corridor::RecoverDepthOptions().level_roll,
            "Estimate the camera's roll from the walls' vertical edges and, when they show it "
            "clearly, recover the frame turned level (for handheld and head-mounted cameras)");
DEFINE_string(solver_evidence, corridor::RecoverDepthOptions().solver_evidence,
              "What the solvers fit: lines (points_per_line points on each fitted junction line) "
              "or edges (each junction's measured sub-pixel edge points, weighted by the gradient "
              "across the edge)");
DEFINE_double(roi_top, 0.5, "Junction search region starts at this fraction of the image height");
DEFINE_double(hough_angle_window, 15.0,
              "Junction search: each edge pixel votes only for lines within this many degrees of "
              "its gradient's direction (oriented Hough); 0 = OpenCV's HoughLinesP, all angles");
DEFINE_int32(relaxed_hough_threshold, 12,
             "Junction search: when no pair of junctions is found, look at the same edges again "
             "with this Hough threshold (votes) and shorter segments, for a faint junction broken "
             "into short pieces (door bottoms); 0 = no second look");
DEFINE_string(sequence, "auto",
              "Run the frames as one stream, in order, so that tracking and the holds of widths "
              "and ceilings apply: auto (videos and ROS bags yes; images, folders and datasets "
              "no: each frame on its own), true or false");
DEFINE_double(min_confidence, corridor::RecoverDepthOptions().min_confidence,
              "Refuse a frame whose confidence (the evidence for its layout, 0-1) is below this; "
              "0 = never refuse on confidence");
DEFINE_double(min_corridor_width, corridor::RecoverDepthOptions().min_width,
              "Refuse a frame whose corridor width is narrower than this, m");
DEFINE_double(max_corridor_width, corridor::RecoverDepthOptions().max_width,
              "Refuse a frame whose corridor width is wider than this, m: wider than a corridor "
              "(a hall), or a rail or a wainscot's top taken for the floor's edge. Raise it for "
              "wide halls");
DEFINE_double(max_floor_texture, 0.015,
              "A floor between the junctions with more strong edges along no corridor line "
              "(horizontal, vertical, toward the vanishing point) than this fraction is not a "
              "corridor floor (outdoor scenes, still lifes): no corridor found. Raise it for "
              "patterned floors; 0 = no check");
DEFINE_int32(floor_band_min_across, 20,
             "A chosen junction with a line above it, where the floor between them shows at least "
             "this many edge pixels across the corridor (tile joints) and few vertical ones, is a "
             "runner's or stripe's edge: the line above is the junction; 0 = off");
DEFINE_double(floor_band_texture_density, 0.02,
              "Also floor for that rule: a band with at least this many edge pixels per pixel, "
              "three times as many oblique ones as vertical or across ones (a carpet's texture "
              "beside a runner); 0 = off");
DEFINE_double(stripe_floor_likeness, 0.7,
              "A chosen junction with a line above it that has the floor's colour beyond it (at "
              "least this alike, in [0, 1]) is a stripe's or border's edge: the next line above "
              "is the junction; 0 = off");
DEFINE_double(inside_floor_likeness, 0.95,
              "A chosen junction with the floor's colour on both sides (the strip above it at "
              "least this alike to the floor below it, in [0, 1]) lies inside the floor: the "
              "nearest line above is the junction; 0 = off");
DEFINE_double(inside_floor_ridge_likeness, 0.9,
              "... or at least this alike when the chosen junction is a thin ridge (a joint "
              "darker or lighter than the floor on both sides), as a joint on a reflecting floor "
              "is; 0 = off");

namespace corridor {

Status RecoverDepthOptionsFromFlags(RecoverDepthOptions* options) {
  *options = RecoverDepthOptions();
  options->solver = FLAGS_solver;
  options->rasterizer = FLAGS_rasterizer;
  options->rasterizer_options.max_range = FLAGS_max_range;
  options->rasterizer_options.max_height = FLAGS_max_height;
  options->ceiling_height = FLAGS_ceiling_height;
  options->estimate_end_wall = FLAGS_end_wall;
  options->ceiling_checks_inner_lines = FLAGS_inner_line_check;
  options->baseboard_feet.same_ratio = FLAGS_baseboard_feet_same_ratio;
  options->baseboard_feet.ceiling_ratio = FLAGS_baseboard_feet_ceiling_ratio;
  options->baseboard_feet.min_across_support = FLAGS_baseboard_feet_across_support;
  options->track_junctions = FLAGS_track_junctions;
  options->tracker.redetect_interval = FLAGS_redetect_interval;
  options->width_prior = FLAGS_width_prior;
  options->max_width_change = FLAGS_max_width_change;
  options->max_ceiling_disagreement = FLAGS_max_ceiling_disagreement;
  options->max_ceiling_change = FLAGS_max_ceiling_change;
  options->points_per_line = FLAGS_points_per_line;
  options->solver_evidence = FLAGS_solver_evidence;
  options->level_roll = FLAGS_level_roll;
  options->search_max_width = FLAGS_search_max_width;
  options->perception.max_work_width = FLAGS_junction_max_width;
  options->perception.baseboard_band_contrast = FLAGS_baseboard_band_contrast;
  options->perception.roi_top_fraction = FLAGS_roi_top;
  options->perception.max_floor_texture = FLAGS_max_floor_texture;
  options->perception.floor_band_min_across = FLAGS_floor_band_min_across;
  options->perception.stripe_floor_likeness = FLAGS_stripe_floor_likeness;
  options->perception.inside_floor_likeness = FLAGS_inside_floor_likeness;
  options->perception.inside_floor_ridge_likeness = FLAGS_inside_floor_ridge_likeness;
  options->perception.floor_band_texture_density = FLAGS_floor_band_texture_density;
  options->perception.hough_angle_window_deg = FLAGS_hough_angle_window;
  options->perception.relaxed_hough_threshold = FLAGS_relaxed_hough_threshold;
  options->min_confidence = FLAGS_min_confidence;
  options->min_width = FLAGS_min_corridor_width;
  options->max_width = FLAGS_max_corridor_width;
  std::unique_ptr<DepthRecoverer> probe;
  return DepthRecoverer::Create(*options, &probe);
}

CameraOverrides CameraOverridesFromFlags() {
  CameraOverrides overrides;
  overrides.camera_file = FLAGS_camera;
  overrides.camera_height = FLAGS_camera_height;
  overrides.fx = FLAGS_fx;
  overrides.fy = FLAGS_fy;
  overrides.cx = FLAGS_cx;
  overrides.cy = FLAGS_cy;
  overrides.hfov_deg = FLAGS_hfov;
  overrides.focal = FLAGS_focal;
  return overrides;
}

Status ResolveSequence(bool stream, bool* sequence) {
  if (FLAGS_sequence == "auto") {
    *sequence = stream;
  } else if (FLAGS_sequence == "true" || FLAGS_sequence == "1") {
    *sequence = true;
  } else if (FLAGS_sequence == "false" || FLAGS_sequence == "0") {
    *sequence = false;
  } else {
    return Status::InvalidArgument("--sequence=" + FLAGS_sequence +
                                   ": the values are auto, true and false");
  }
  return Status::Ok();
}

void RewriteBareSequenceFlag(int argc, char** argv) {
  static char kTrue[] = "--sequence=true";
  static char kFalse[] = "--sequence=false";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg == "--sequence" || arg == "-sequence") argv[i] = kTrue;
    if (arg == "--nosequence" || arg == "-nosequence") argv[i] = kFalse;
  }
}

}  // namespace corridor
