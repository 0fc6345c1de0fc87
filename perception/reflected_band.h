#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "corridor_depth/junction_lines.h"

namespace corridor {

// How far the reflection's colour may lie from the blend of the floor and the baseboard that the
// floor's gloss makes, as a fraction of the wall/baseboard contrast.
constexpr double kMaxGlossResidual = 0.25;

// On a polished floor a baseboard's reflection lies just below the junction, and the band of
// baseboard and reflection reads as one: its lower edge, the reflection's, is taken for the
// junction, which puts the wall too near by h / (h + b) for a baseboard b high and a camera h
// high. Seen from the vanishing point, lines on the wall at height z have slopes (below the
// horizontal) in proportion to h - z: the baseboard's top (b), the junction (0) and the
// reflection's lower edge (-b) have slopes in proportion to h - b, h and h + b, so the junction is
// the band's middle in slope. The band is a reflection when its lower half's colour is a blend of
// its upper half's and the floor's below it (the mirrored baseboard, dimmed toward the floor);
// a baseboard above a true junction has one colour over the whole band, and is left alone.
// `max_gloss_residual`: how near the blend the reflection must be (kMaxGlossResidual).
//
// From `junction` (raw pixels of the 8-bit BGR `image`, through `vanishing_point`), the band's top
// is the largest colour change toward the wall within `max_turn_deg`. True, with *turn_deg the
// junction's turn toward the floor (negative: toward the wall, for TurnJunctionToFoot), when the
// band is a reflection. `left`: the left wall's junction (the floor lies to its right).
bool FindReflectedJunction(const cv::Mat& image, const JunctionLine& junction,
                           const Eigen::Vector2d& vanishing_point, bool left, double max_turn_deg,
                           double* turn_deg, double max_gloss_residual = kMaxGlossResidual);

// The other way round: `top` (raw pixels, through `vanishing_point`) is a baseboard's top taken
// for the junction, and below it the baseboard and its reflection read as one band down to the
// reflection's lower edge (the largest colour change toward the floor within `max_turn_deg`).
// True, with *turn_deg the turn toward the floor (positive, for TurnJunctionToFoot) to the band's
// middle in slope, the junction, when the band reads as a baseboard above its reflection (as in
// FindReflectedJunction) at least 4% of the camera's height high.
bool FindJunctionBelowBandTop(const cv::Mat& image, const JunctionLine& top,
                              const Eigen::Vector2d& vanishing_point, bool left,
                              double max_turn_deg, double* turn_deg);

// Whether `junction` already lies at the middle of such a band: the baseboard above it and its
// reflection below it, down to the reflection's lower edge as far below in slope as the band's top
// is above. A wall whose junction was found between the two, on the same polished floor.
bool JunctionAtReflectedBandsMiddle(const cv::Mat& image, const JunctionLine& junction,
                                    const Eigen::Vector2d& vanishing_point, bool left,
                                    double max_turn_deg);

// The band above `junction` as FindReflectedJunction reads it (its top: the largest colour change
// toward the wall within `max_turn_deg`, of at least the least wall/baseboard contrast): its height
// relative to the camera's, 1 - tan(top) / tan(junction) in slopes below the horizontal (a wall
// line at height z has a slope in proportion to h - z), and the turn toward the floor (negative)
// to its middle in slope. Both walls stand on one floor with one baseboard: when one wall's
// junction is a reflection's lower edge, the other wall's band of the same relative height ends
// at its reflection's lower edge too, even where that reflection is too like its baseboard to be
// told apart. False when there is no such band.
bool BandAboveJunction(const cv::Mat& image, const JunctionLine& junction,
                       const Eigen::Vector2d& vanishing_point, bool left, double max_turn_deg,
                       double* relative_height, double* middle_turn_deg);

}  // namespace corridor
