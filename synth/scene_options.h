#pragma once

#include <cstdint>
#include <string>

namespace corridor {
namespace synth {

// What a generated corridor contains. Ranges are checked by Check().
struct SceneOptions {
  double width = 2.2;                // Wall-to-wall width, m [0.8, 20].
  double ceiling_height = 2.7;       // Ceiling above the floor, m [1.8, 10].
  double length = 40.0;              // Distance from the corridor's start to its end wall, m [5, 500].
  double clutter = 0.0;              // Boxes and bins on the floor near the walls, [0, 1].
  double door_density = 0.5;         // Chance of a door every 5 m along each wall, [0, 1].
  double floor_wall_contrast = 1.0;  // 1 = strongly different floor and walls, 0 = the same, [0, 1].
  double baseboard_height = 0.1;     // Baseboard height, m [0, 0.3] (0 = none).
  double baseboard_contrast = 0.6;   // How much darker the baseboard is than the wall, [0, 1].
  double tile_size = 0.6;            // Floor tile edge, m [0.1, 2]; grout runs both ways.
  bool lights = true;                // Bright ceiling light panels every 3 m.
  double falloff = 0.002;            // Light falloff: brightness / (1 + falloff * distance^2), [0, 1].
  double blur_sigma = 0.6;           // Gaussian blur of the final image, px [0, 5].
  double noise_sigma = 2.0;          // Gaussian sensor noise, grey levels [0, 50].
  uint32_t seed = 1;                 // Everything random derives from this seed.

  // Parts of real buildings that look like junctions (all off by default; their sizes, colours
  // and positions are drawn from the seed; docs/generator.md states their ranges).
  bool handrails = false;          // Rails on brackets a few cm out from the walls (solids).
  bool chair_rails = false;        // Mouldings on the walls at chair height (solids).
  bool wainscot = false;           // Two-tone walls: a lower panel and its cap line (paint).
  double furniture = 0.0;          // Benches, sofas, lockers, radiators, carts, [0, 1] (solids).
  bool runner = false;             // A carpet runner along the corridor (paint).
  bool floor_stripes = false;      // Painted stripes along the corridor near the walls (paint).
  bool carpet = false;             // Carpeted floor: no grout, fine texture (paint).
  bool glass_walls = false;        // Glass runs in the walls; a lit room shows behind (plane).
  bool window_bands = false;       // A row of windows above a sill along one wall.
  bool pillars = false;            // Pillars standing out of the walls, floor to ceiling (solids).
  double floor_gloss = 0.0;        // A polished floor: this share of its colour is the mirrored ray's
                                   // (the baseboard's, the walls', reflected), [0, 0.8].
  double floor_gloss_reach = 0.0;  // A satin floor, m: the mirrored share fades as
                                   // exp(-distance / reach) along the mirrored ray (strong at a
                                   // wall's foot, gone a little way out); 0 = a mirror, [0, 5].

  bool Check(std::string* why) const;
};

// Where the camera is, with the signs of docs/geometry.md.
struct CameraPose {
  double pitch = 0.0;     // theta > 0: pitched down, rad.
  double yaw = 0.0;       // phi > 0: the corridor axis appears right of cx, rad.
  double offset = 0.0;    // tau > 0: right of the centre line, m.
  double height = 0.66;   // Optical centre above the floor, m.
  double distance = 2.0;  // Position along the corridor from its start, m.
  double roll = 0.0;      // About the optical axis after pitch and yaw, rad; > 0: the image's
                          // right side shows the scene lower (a nuisance the model lacks).
};

}  // namespace synth
}  // namespace corridor
