#pragma once

// The options of the pipeline's stages, gathered in RecoverDepthOptions.

#include <string>

namespace corridor {

// Options of the junction-line detector (paper III-A). Defaults are the paper's where it gives
// one, and work on generated and real corridors.
struct JunctionDetectorOptions {
  double roi_top_fraction = 0.5;                    // The search region starts at this fraction of the height (paper: the middle).
  double blur_sigma = 0.8;                          // Gaussian blur before Canny, px (0 = none).
  double canny_high = 0;                            // Canny high threshold on |dx|+|dy| (Sobel 3x3); 0 = automatic.
  double canny_low_ratio = 0.4;                     // Canny low threshold as a fraction of the high one.
  double canny_auto_percentile = 90;                // Automatic high threshold: this percentile of the ROI's gradients...
  double canny_auto_min = 40;                       // ... but at least this, so that flat images give no edges.
  int hough_threshold = 25;                         // Probabilistic Hough accumulator threshold (votes).
  double hough_min_length_fraction = 0.04;          // Shortest Hough segment, as a fraction of the image height.
  double hough_max_gap = 6;                         // Largest gap bridged inside one Hough segment, px.
  double hough_angle_window_deg = 15;               // Each edge pixel votes only for lines within this of its gradient's direction (OrientedHoughSegments); 0 = cv::HoughLinesP, all angles.
  int relaxed_hough_threshold = 12;                 // When no pair is found, Hough looks again at the same edges with this threshold (votes): a faint junction broken by door bottoms gives only short pieces; 0 = no second look.
  double relaxed_hough_min_length_fraction = 0.02;  // ... and this shortest segment, fraction of the height.
  double relaxed_min_line_fraction = 0.2;           // A line found only on the second look is at least this long, fraction of the height (a broken junction spans much of the image; chance alignments are short).
  double relaxed_min_partner_boundary = 0.1;        // ... and pairs only with a first-look line whose BoundaryScore (floor below, something else above) is at least this.
  double merge_angle_deg = 2.5;                     // Segments whose angles differ less than this may merge (the paper's NMS).
  double merge_distance_px = 4;                     // ... and whose lines pass within this distance of each other.
  double min_length_fraction = 0.1;                 // Scene prior (eq. 2): shortest junction, fraction of the height H (paper: 0.25).
  double max_length_fraction = 0.75;                // Scene prior (eq. 2): longest junction, fraction of the diagonal (paper 1/2); 0 = no limit.
  double min_inclination_deg = 8;                   // Scene prior: flattest junction, degrees from horizontal (cross-corridor edges are flatter).
  double max_inclination_deg = 80;                  // Scene prior: steepest junction, degrees from horizontal (the paper: 90 - atan(H/W), set -1).
  double baseboard_band_contrast = 1.45;            // A lower line parallel to the chosen one is the junction (the chosen one a baseboard top) when the band between them is this unlike the floor below, in floor spreads (BandContrast); raise it for glossy floors that mirror the baseboard; 0 = off.
  int floor_band_min_across = 20;                   // The chosen junction is a line inside the floor (a runner's or stripe's edge) and a line above it the junction when the band between them has at least this many edge pixels across the corridor (tile joints), few vertical ones (FloorBandTest); 0 = off.
  double floor_band_texture_density = 0.02;         // ... or, for the floor rule, a textured floor (carpet): at least this many edge pixels per band pixel, three times as many oblique ones as vertical or across ones; 0 = off.
  double stripe_floor_likeness = 0.7;               // The chosen junction is a stripe's or border's edge when a line above it has floor at least this alike (FloorLikenessAbove, in [0, 1]) beyond it: the next line above is the junction (FloorBandTest::floor_above); 0 = off.
  double inside_floor_likeness = 0.95;              // The chosen junction lies inside the floor (a tile joint or a runner's edge beside the wall) when the strip just above it is at least this alike to the floor just below it (FloorLikenessAbove, in [0, 1]): the nearest line above is the junction; 0 = off.
  double inside_floor_ridge_likeness = 0.9;         // ... or at least this alike when the chosen junction is a thin ridge (a joint darker or lighter than the floor on both sides, RidgeFraction) and the band up to the next line has no more vertical edges than twice its edges across: a reflection on a satin floor makes the strip above a joint a little less alike; 0 = off.
  double support_distance_px = 2.0;                 // Edge pixels this close to a chosen line support its refit.
  double max_edge_density = 0.2;                    // More edge pixels than this fraction of the ROI: noise or texture, not a corridor.
  double max_floor_texture = 0.015;                 // More of the floor between the chosen junctions in strong edges along no corridor line than this fraction: not a corridor (an outdoor scene, a still life); 0 = no check.
  int strong_edge_gradient = 240;                   // A strong edge: colour |dx| + |dy| (Sobel 3x3) at least this, a step of about 60 grey levels.
  double floor_line_tolerance_deg = 15;             // Floor edges within this of horizontal, vertical or the vanishing point are corridor lines (joints, tape, reflections).
  int max_work_width = 640;                         // Wider images are halved (pyrDown) until they fit before edges and lines are found; 0 = full resolution.
  bool refit_full_resolution = true;                // After a search on a halved image, each chosen junction is refitted on the full-resolution gradient (RefitJunctionAtFullResolution).

  bool Check(std::string* why) const;
};

// Options of the junction tracker: in a sequence, the junctions are sought again in bands around
// the previous frame's instead of in the whole search region.
struct JunctionTrackerOptions {
  double reach_fraction = 0.04;       // A band reaches this far either side of the previous line, along rows (columns), fraction of the image height.
  int sample_step = 2;                // Edge points are sought on every this many rows (columns) of the detector's working scale.
  double threshold = 20;              // Least colour gradient across the line (Sobel 3x3, the strongest channel) of an edge point.
  double min_support = 0.4;           // Least fraction of a band's rows (columns) with an edge point on a line for it to be a candidate.
  double max_shift_fraction = 0.03;   // The junctions may have moved at most this far from the previous ones (mean offset at the band's ends), fraction of the image height; farther, the whole region is searched.
  int max_lines_per_band = 4;         // At most this many candidate lines per band, the best supported.
  double extend_fraction = 0.15;      // The previous line's extent is searched lengthened by this fraction at each end.
  double support_distance_px = 2;     // Edge points this close to a candidate line support it, px.
  int redetect_interval = 10;         // After this many tracked frames in a row the whole region is searched again, and checked against its tracked pair (0 = never again once trusted).
  double agreement_px = 2;            // A tracked and a searched junction within this of each other at both ends are the same line, px.
  double min_line_confidence = 0.15;  // A tracked line weaker than this (JunctionLine::confidence; the frame confidence counts it as weak) leaves the frame to the whole search.

  bool Check(std::string* why) const;
};

// Finding the ceiling height once the walls are known (beyond the paper; docs/geometry.md s6).
struct CeilingDetectorOptions {
  double min_height = 1.8;             // Lowest ceiling considered, m above the floor.
  double max_height = 6.0;             // Highest ceiling considered, m above the floor.
  double step = 0.01;                  // Search step of the ceiling height, m.
  double near_distance = 1.0;          // Junction samples from this distance along the corridor, m...
  double far_distance = 30.0;          // ... to this one.
  int samples = 80;                    // Samples per junction line.
  double min_support = 0.35;           // Fraction of a line's visible samples on edges to accept it.
  double min_counted_fraction = 0.25;  // ... counting at least this fraction of `samples` as visible (a high ceiling, or a narrow vertical field of view, shows its junction only from a few metres on).

  bool Check(std::string* why) const;
};

// Finding a wall across the corridor once the side walls are known (beyond the paper): the
// floor/end-wall junction is the line (X, h, D), -d_l <= X <= d_r, of the corridor frame. It must
// follow the image's edges over two thirds of the width at least, and a floor/wall junction must end there
// (their continuation behind it is hidden), and at least one vertical wall/end-wall corner must
// show, and the wall above the line must look unlike the floor before it. Tile grout and door
// sills across the floor follow the edges too, but the junctions go on beyond them, they have no
// corners and floor lies on both sides: they are not taken for an end wall.
struct EndWallDetectorOptions {
  double near_distance = 1.5;  // Nearest end wall considered, m along the corridor.
  double far_distance = 20.0;  // Farthest, m (farther, the floor/end-wall line is too few pixels to tell).
  int candidates = 0;          // Candidate distances, uniform in 1/D between near and far (0 = as many as reach_px needs).
  int samples = 60;            // Samples along each searched line.
  double min_support = 0.6;    // Fraction of the floor/end-wall line's samples on edges, in two of its thirds.
  double max_beyond = 0.3;     // Largest fraction of the cleaner junction's samples on edges just beyond the wall.
  double min_before = 0.4;     // Least fraction of a junction's samples on edges just before it (one side).
  double min_corner = 0.5;     // Least fraction of a vertical corner's samples on edges (one side).
  double min_contrast = 6.0;   // Least Lab distance (appearance.h) of the wall just above the line from the floor before it (0 = off).
  double min_span = 0.08;      // Visible length of the floor/end-wall line, as a fraction of the image width.
  int reach_px = 2;            // A sample is on an edge within this many px (the geometry is not exact).
  int max_work_width = 480;    // Wider images are searched at half resolution (or less), px.

  bool Check(std::string* why) const;
};

// Two ceiling junctions, each plainly seen, that no one ceiling height explains, where moving one
// wall to the height the other's ceiling gives puts a junction on a line that follows the image's
// edges: there are two layouts, and the image's lines fit both (a baseboard's top, a rail or a
// runner's edge on both sides, and the true junction fainter). The one reported may be either, so
// the frame's confidence drops (FrameConfidence): right or refused.
struct CeilingSplitOptions {
  double min_visible_support = 0.6;      // Each side's own best ceiling junction on edges over this fraction of its samples in view.
  double max_joint_support = 0.3;        // At the ceiling height the two sides best share, one side's junction on edges over less than this fraction.
  double min_disagreement = 0.18;        // The two sides' heights above the camera this much (relative) apart at least (a head-mounted camera's roll, up to 3 degrees, which the model lacks, puts right frames' sides up to 17% apart).
  double min_alternative_support = 0.5;  // A floor junction where either move would put it (within 8%) on edges over this fraction of its view.
  bool Check(std::string* why) const;
};

struct VerticalCrossingOptions {
  double band_height = 0.25;        // How far above (and as far in pixels below) the junction to look, m on the wall.
  double min_band_px = 5;           // Junction points whose band is shorter are not examined, px.
  double max_band_px = 24;          // Longer bands (near the camera) are cut to this, px.
  double min_step = 8;              // An edge is a step of at least this many grey levels in each channel.
  double min_run = 0.7;             // A vertical edge must cover this fraction of a band.
  double min_contrast_ratio = 0.7;  // Below the junction, an edge of less than this fraction of the contrast above is a reflection.
  int step_px = 2;                  // Junction points every this many pixels.
  bool Check(std::string* why) const;
};

// A junction taken from a line inside the floor (a grout line, a box's bottom edge, a rug's edge:
// all parallel to the corridor, so the vanishing point, yaw and pitch stay right) puts its wall
// too near, by the same factor as the height of the ceiling its own ceiling/wall junction gives:
// the ceiling junctions, each searched alone over a wide range of heights, then disagree, and the
// side with the lower ceiling is the one too near. That wall is moved out, by the ratio of the two
// heights, to where its ceiling junction meets the other side's ceiling.
// The same disagreement comes from the other wall put too far, by a baseboard's top taken for its
// junction (its wall distance and ceiling scaled up by h / (h - baseboard height)). The two are
// told apart by the band each move would cross: moving the near wall out crosses floor (a line
// inside the floor to the junction), moving the far wall in crosses the baseboard (its top to the
// junction below it). When both bands look unlike the floor, the far wall is moved in instead.
struct InnerLineCheckOptions {
  double min_disagreement = 0.15;            // Least relative difference of the two sides' ceiling heights that moves a wall.
  double min_support = 0.35;                 // Least fraction of each side's ceiling junction on edges (the ceiling search's own minimum), counted over at least half its samples.
  double strong_support = 0.45;              // When the trusted side reaches min_support only on its samples in view (a narrow vertical view shows its junction from a few metres on), the side to move needs this much, of at least half its samples.
  double min_above_camera = 0.2;             // The wide search: ceilings from this far above the camera, m, up to the ceiling search's max_height.
  double max_line_support = 0.8;             // A floor junction on edges of its orientation over this fraction of its samples in view (sampled as the ceiling search samples its lines) is not moved: a box's edge or floor line covers less.
  double min_band_contrast = 1.45;           // Both bands (see above) at least this unlike the floor below them (BandContrast, in floor spreads): a baseboard's top was taken on the far side, which moves in; 0 = never.
  double min_baseboard_disagreement = 0.08;  // Least relative difference of the two sides' ceiling heights that moves the far wall in (a baseboard's top is a few per cent of the camera height above the floor).
  double max_baseboard_height = 0.2;         // The far wall moves in only as far as a baseboard's top this high explains (h / (h - b), h the camera height), m; 0 = no limit.
  double min_target_support = 0.02;          // A wall moves only where its new junction follows edges (CorridorLineSupport, best within 8% of the move) on at least this fraction of its view: a junction hidden all along, or a wall's plain face, cannot confirm a move; 0 = no check.
  double far_max_height = 15.0;              // A side with no ceiling junction up to the ceiling search's max_height, the other's plainly seen: its ceiling is sought up to this height, m; found, its wall is too far (a line through a glass wall or a recess's floor taken for its junction) and moves in; 0 = never.
  double min_far_ceiling_support = 0.6;      // ... when both ceiling junctions, the other side's and the far side's moved in, are plainly seen: on edges over this fraction of their samples in view.
  double min_far_target_support = 0.3;       // ... and only where its new junction follows edges (as min_target_support) on at least this fraction of its view.

  bool Check(std::string* why) const;
};

// Both walls on their baseboards' tops scale the whole box up by h / (h - b) (h the camera's
// height, b the baseboard's): the two ceiling sides still agree, so no ceiling check sees it. A
// corridor's baseboards are one height on both walls. Below each junction a band may have a lower
// edge (FindLowerEdge); when the two feet move both walls in by one ratio r, giving one baseboard
// height b = h (1 - 1 / r), and each band is unlike the floor beyond its foot, the feet are the
// junctions. A polished floor's reflection of the baseboard makes the same pair of bands below
// correct junctions (r = (h + b) / h): there the baseboard's top stands above each junction, at
// the wall distance d / (2 - r), on edges; above a baseboard's top there is only wall. A satin
// floor's reflection fades from the junction into the floor; a painted baseboard is one colour.
// One wall on its baseboard's top raises its ceiling side by the same h / (h - b): a foot that
// moves that wall in by the ratio of the two ceiling sides is its junction. Otherwise (the ceiling
// too weak to say, or read off other lines) the other wall tells: its baseboard's top stands at the
// height b the foot gives, while the wall moved shows no band top at b above its line first taken
// (as it would, were that line its foot).
struct BaseboardFeetOptions {
  double same_ratio = 0.015;        // Both walls: their ratios agree within this (relative); 0 = off.
  double ceiling_ratio = 0.03;      // One wall: its foot's ratio and its ceiling side's over the other's agree within this (relative); 0 = off.
  double min_height = 0.03;         // Least baseboard height the ratio may imply, m.
  double max_height = 0.2;          // Greatest, m.
  double min_band_contrast = 1.0;   // Each band at least this unlike the floor beyond its foot (BandContrast, in floor spreads: more than the floor's own spread).
  double max_band_fade = 0.85;      // Each band's change from a quarter to three quarters of the way down at most this fraction of its middle's step to the floor beyond (BandFade: 0 for one colour, about 1 for a ramp into the floor).
  double min_across_support = 0.5;  // One wall, the ceiling sides not agreeing on its ratio: the other wall's band top at the foot's height b on edges over this fraction of its view (CorridorLineSupport); 0 = off.
  double max_above_support = 0.25;  // ... and the wall moved shows no band top at b above its line first taken: on edges over at most this fraction of its view.
  double max_mirror_support = 0.5;  // A line above either junction where a reflected baseboard's top would be, on edges over this fraction of its view (CorridorLineSupport): the bands are reflections.

  bool Check(std::string* why) const;
};

}  // namespace corridor
