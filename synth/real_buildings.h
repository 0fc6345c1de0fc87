#pragma once

#include <string>
#include <vector>

#include "corridor_depth/status.h"
#include "synth/presets.h"

namespace corridor {
namespace synth {

// The real-buildings preset: corridors with the parts of real buildings that look like a
// floor/wall junction, one class at a time or all mixed, so that each failure class is measured
// on its own. A class is `scenes` scenes of `frames` frames (default 10 x 20 = 200) at
// width_px x height_px (default 640x480, hfov 80 deg). Scene i of a class has seed
// ClassSeed(class) + 7 i; everything in it (sizes, colours, positions, poses) follows from it.
//
// Every scene (all classes): width 1.6-3.2 m, ceiling 2.4-3.2 m, length 35-60 m, door density
// 0.2-0.6, floor/wall contrast 0.5-1.0, baseboard contrast 0.2-0.8, no clutter boxes.
// Robot camera (all classes but head and low): height 0.55-0.75 m, pitch 0-0.10 rad down.
// Every frame: yaw +-0.12 rad, offset +-0.3 of the half-width, 1.5 + 0.8 i m into the corridor.
//
// Classes and their parts (drawn per scene in BuildScene, see docs/generator.md):
//   rail       handrails (top 0.8-1.1 m, 3-6 cm thick, 4-8 cm out from the wall, on one or both
//              walls) and/or chair rails (centre 0.8-1.0 m, 4-8 cm tall, 1.2-3 cm out, both
//              walls); wood, metal, dark or wall-coloured; broken at doors and pillars.
//   wainscot   lower wall panel up to 0.8-1.2 m, darker, wood or another colour; half with a
//              2-5 cm cap line.
//   furniture  benches, sofas, lockers, radiators, carts against the walls (density 0.5-1.0:
//              about one piece per 4-8 m), 0-5 cm from the wall (carts 5-30 cm), depth up to
//              0.4 of the width.
//   floor      a carpet runner (0.35-0.7 of the width, centre +-0.1 width, half with a border)
//              and/or painted stripes (4-12 cm wide, 0.1-0.5 m from each wall).
//   carpet     carpeted floor: texture cells 1-3 cm, brightness +-8-30%.
//   glass      glass runs 3-10 m long in one or both walls, floor to ceiling or 2.0-2.4 m high,
//              a lit room 2-7 m deep behind (0.4-1.4 x the corridor's light), mullions every
//              0.9-1.8 m, a 0-12 cm base rail. The truth is the glass plane.
//   windows    a band of windows on one wall, sill 0.8-1.1 m (a solid ledge 3-10 cm out), top
//              1.8-2.3 m, panes 0.8-2.0 m with 8-40 cm mullions, a bright view outside.
//   pillars    pillars every 3.5-8 m on one or both walls, 0.1-0.35 m out (<= 0.2 width),
//              0.3-0.6 m wide, floor to ceiling, wall colour x 0.8-1.1.
//   head       head-mounted or handheld camera: height 1.4-1.8 m, pitch 5-30 deg down, roll
//              +-3 deg (the truth depth is ray-cast with the roll; truth.yaml has no roll).
//   low        low robot: height 0.2-0.5 m, pitch 0-0.08 rad down.
//   mix        every part with chance 0.4 (furniture 0-0.8), camera robot 40%, head 40%, low 20%.
//   glossy     a polished floor: 0.25-0.6 of its colour is the mirrored view (the baseboard and
//              the walls reflected below the junction). Not part of mix, which keeps its scenes.
//   satin      a satin floor: 0.3-0.7 of its colour is the mirrored view at a wall's foot, fading
//              as exp(-d / reach) along the mirrored ray, reach 0.03-0.3 m: a baseboard's blurred
//              reflection that fades out into the floor. Not part of mix.
//   baseboard  baseboards 0.04-0.22 m high (every other class draws 0.1 m), contrast 0-0.9 (0 =
//              the wall's colour: no line at the baseboard's top). Not part of mix.
const std::vector<std::string>& RealBuildingClasses();

// The class's base seed (named in docs/results.md): 2900 + 100 x its index in the list above.
uint32_t RealBuildingSeed(const std::string& name);

struct RealBuildingsOptions {
  int scenes = 10;
  int frames = 20;
  int width_px = 640;
  int height_px = 480;
  double hfov_deg = 80.0;
};

// The scenes of one class (or of every class, "all", scene names prefixed by the class).
Status RealBuildingsPreset(const std::string& name, const RealBuildingsOptions& options,
                           std::vector<ScenePreset>* presets);

}  // namespace synth
}  // namespace corridor
