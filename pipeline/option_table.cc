#include "pipeline/option_table.h"

namespace corridor {

void VisitRecoverDepthOptions(RecoverDepthOptions* o, OptionVisitor* v) {
  v->String("solver", &o->solver);
  v->String("rasterizer", &o->rasterizer);
  v->Double("max_range", &o->rasterizer_options.max_range);
  v->Double("max_height", &o->rasterizer_options.max_height);
  v->Double("ceiling_height", &o->ceiling_height);
  v->Bool("end_wall", &o->estimate_end_wall);
  v->Bool("inner_line_check", &o->ceiling_checks_inner_lines);
  v->Double("baseboard_feet_same_ratio", &o->baseboard_feet.same_ratio);
  v->Double("baseboard_feet_ceiling_ratio", &o->baseboard_feet.ceiling_ratio);
  v->Double("baseboard_feet_across_support", &o->baseboard_feet.min_across_support);
  v->Bool("track_junctions", &o->track_junctions);
  v->Int("redetect_interval", &o->tracker.redetect_interval);
  v->Double("width_prior", &o->width_prior);
  v->Double("max_width_change", &o->max_width_change);
  v->Double("max_ceiling_disagreement", &o->max_ceiling_disagreement);
  v->Double("max_ceiling_change", &o->max_ceiling_change);
  v->Int("points_per_line", &o->points_per_line);
  v->String("solver_evidence", &o->solver_evidence);
  v->Bool("level_roll", &o->level_roll);
  v->Int("search_max_width", &o->search_max_width);
  v->Int("junction_max_width", &o->perception.max_work_width);
  v->Double("baseboard_band_contrast", &o->perception.baseboard_band_contrast);
  v->Double("roi_top", &o->perception.roi_top_fraction);
  v->Double("max_floor_texture", &o->perception.max_floor_texture);
  v->Int("floor_band_min_across", &o->perception.floor_band_min_across);
  v->Double("floor_band_texture_density", &o->perception.floor_band_texture_density);
  v->Double("stripe_floor_likeness", &o->perception.stripe_floor_likeness);
  v->Double("inside_floor_likeness", &o->perception.inside_floor_likeness);
  v->Double("inside_floor_ridge_likeness", &o->perception.inside_floor_ridge_likeness);
  v->Double("hough_angle_window", &o->perception.hough_angle_window_deg);
  v->Int("relaxed_hough_threshold", &o->perception.relaxed_hough_threshold);
  v->Double("min_confidence", &o->min_confidence);
  v->Double("min_corridor_width", &o->min_width);
  v->Double("max_corridor_width", &o->max_width);
}

}  // namespace corridor
