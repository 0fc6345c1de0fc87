#pragma once

#include <gflags/gflags.h>

#include "corridor_depth/status.h"
#include "corridor_depth/recover_depth.h"
#include "tools/input_source.h"
#include "tools/tool_help.h"  // CheckFlagNames

// The flags every tool that recovers depth takes (corridor_depth, corridor_eval, ...).
DECLARE_string(camera);
DECLARE_double(camera_height);
DECLARE_double(fx);
DECLARE_double(fy);
DECLARE_double(cx);
DECLARE_double(cy);
DECLARE_double(hfov);
DECLARE_string(focal);
DECLARE_string(solver);
DECLARE_string(rasterizer);
DECLARE_double(max_range);
DECLARE_double(max_height);
DECLARE_double(ceiling_height);
DECLARE_bool(end_wall);
DECLARE_bool(inner_line_check);
DECLARE_double(baseboard_feet_same_ratio);
DECLARE_double(baseboard_feet_ceiling_ratio);
DECLARE_double(baseboard_feet_across_support);
DECLARE_double(width_prior);
DECLARE_double(max_width_change);
DECLARE_double(max_ceiling_disagreement);
DECLARE_double(max_ceiling_change);
DECLARE_int32(points_per_line);
DECLARE_string(solver_evidence);
DECLARE_bool(level_roll);
DECLARE_int32(search_max_width);
DECLARE_int32(junction_max_width);
DECLARE_double(baseboard_band_contrast);
DECLARE_double(roi_top);
DECLARE_double(max_floor_texture);
DECLARE_int32(floor_band_min_across);
DECLARE_double(stripe_floor_likeness);
DECLARE_double(inside_floor_likeness);
DECLARE_double(inside_floor_ridge_likeness);
DECLARE_double(floor_band_texture_density);
DECLARE_double(hough_angle_window);
DECLARE_int32(relaxed_hough_threshold);
DECLARE_string(sequence);
DECLARE_double(min_confidence);

namespace corridor {

// RecoverDepthOptions from the flags, checked; InvalidArgument names the bad flag.
Status RecoverDepthOptionsFromFlags(RecoverDepthOptions* options);
CameraOverrides CameraOverridesFromFlags();

// --sequence=auto|true|false for a scene: `stream` is true for a video or a ROS bag, which auto
// runs as one sequence (tracking, held widths and ceilings); images, folders and datasets are
// independent frames. InvalidArgument for another value.
Status ResolveSequence(bool stream, bool* sequence);

// Call first: a bare --sequence (or --nosequence), as the flag was once a boolean, becomes
// --sequence=true (false), since gflags would take the next argument as a string flag's value.
void RewriteBareSequenceFlag(int argc, char** argv);

}  // namespace corridor
