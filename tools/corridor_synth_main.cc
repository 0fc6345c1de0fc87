// corridor_synth: synthetic corridors with exact ground truth, in the dataset layout.
//   corridor_synth --preset=paper --output_dir=D      (the paper's 9 scenes x 15 frames)
//   corridor_synth --preset=paper --paper_scale=1.5 --output_dir=D   (the same at 630x540)
//   corridor_synth --preset=sequence --frames=30 --corridor_width=2.5 --output_dir=D
//   corridor_synth --preset=single --yaw=0.1 --pitch=0.05 --output_dir=D
//   corridor_synth --preset=real_buildings --real_class=rail --output_dir=D  (200 frames)
//   corridor_synth --preset=single --handrails --glass_walls --roll=0.03 --output_dir=D

#include <cmath>
#include <cstdio>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "synth/presets.h"
#include "synth/real_buildings.h"
#include "synth/sequence.h"
#include "tools/progress.h"
#include "tools/tool_help.h"

DEFINE_string(preset, "sequence",
              "paper (9 scenes x 15 frames), real_buildings (see --real_class), sequence, or single");
DEFINE_string(output_dir, "", "Dataset root to write");
DEFINE_double(paper_scale, 1.0,
              "paper preset: pixels per paper pixel (1.5 gives 630x540, fx 375: the same views)");
DEFINE_string(scene_name, "corridor", "Scene folder name for the single and sequence presets");
DEFINE_int32(width_px, 640, "Image width, px (single, sequence)");
DEFINE_int32(height_px, 480, "Image height, px (single, sequence)");
DEFINE_double(fx, 0, "Focal length, px (0: from --hfov); fy = fx; principal point centred");
DEFINE_double(hfov, 80, "Horizontal field of view when --fx is 0, degrees");
DEFINE_double(hfov_deg, 80, "Old name of --hfov");
DEFINE_double(corridor_width, 2.2, "Corridor width, m");
DEFINE_double(ceiling_height, 2.7, "Ceiling height, m");
DEFINE_double(length, 40, "Distance to the end wall, m");
DEFINE_double(camera_height, 0.66, "Camera height above the floor, m");
DEFINE_double(pitch, 0.05, "Camera pitch, rad (> 0 down)");
DEFINE_double(yaw, 0.0, "Camera yaw, rad (> 0: corridor axis right of centre)");
DEFINE_double(offset, 0.0, "Lateral offset, m (> 0: camera right of the centre line)");
DEFINE_double(distance, 2.0, "Camera distance from the corridor's start, m (first frame)");
DEFINE_double(clutter, 0.2, "Boxes near the walls, [0, 1]");
DEFINE_double(door_density, 0.5, "Doors, [0, 1]");
DEFINE_double(contrast, 0.9, "Floor/wall contrast, [0, 1]");
DEFINE_int32(frames, 15, "Frames (sequence)");
DEFINE_uint32(seed, 1, "Random seed");
DEFINE_double(roll, 0.0, "Camera roll about the optical axis, rad (> 0: the right side lower)");
DEFINE_bool(handrails, false, "Handrails along the walls (single, sequence)");
DEFINE_bool(chair_rails, false, "Chair rails on the walls (single, sequence)");
DEFINE_bool(wainscot, false, "Two-tone walls with a wainscot line (single, sequence)");
DEFINE_double(furniture, 0.0, "Benches, sofas, lockers, radiators, carts, [0, 1]");
DEFINE_bool(runner, false, "A carpet runner along the corridor (single, sequence)");
DEFINE_bool(floor_stripes, false, "Painted stripes along the corridor (single, sequence)");
DEFINE_bool(carpet, false, "Carpeted floor with texture (single, sequence)");
DEFINE_bool(glass_walls, false, "Glass runs in the walls with a room behind (single, sequence)");
DEFINE_bool(window_bands, false, "A band of windows along one wall (single, sequence)");
DEFINE_bool(pillars, false, "Pillars standing out of the walls (single, sequence)");
DEFINE_double(floor_gloss, 0.0,
              "A polished floor: the share of its colour that is the mirrored view, [0, 0.8] "
              "(single, sequence)");
DEFINE_double(floor_gloss_reach, 0.0,
              "A satin floor: the mirrored view fades as exp(-distance / reach) along its ray, m; "
              "0 = a mirror, [0, 5] (single, sequence)");
DEFINE_string(real_class, "all",
              "real_buildings: all, or one class: rail, wainscot, furniture, floor, carpet, glass, "
              "windows, pillars, head, low, mix, glossy, satin, baseboard");
DEFINE_int32(real_scenes, 10, "real_buildings: scenes per class, [1, 14]");
DEFINE_int32(real_frames, 20, "real_buildings: frames per scene, [1, 40]");

namespace corridor {
namespace {

int Usage(const std::string& message) {
  std::fprintf(stderr, "corridor_synth: %s\n", message.c_str());
  return 2;
}

bool MakeCustomPreset(synth::ScenePreset* preset, std::string* why) {
  preset->name = FLAGS_scene_name;
  if (preset->name.empty() || preset->name.find('/') != std::string::npos) {
    *why = "--scene_name must be a plain folder name";
    return false;
  }
  synth::SceneOptions& s = preset->scene;
  s.width = FLAGS_corridor_width;
  s.ceiling_height = FLAGS_ceiling_height;
  s.length = FLAGS_length;
  s.clutter = FLAGS_clutter;
  s.door_density = FLAGS_door_density;
  s.floor_wall_contrast = FLAGS_contrast;
  s.seed = FLAGS_seed;
  s.handrails = FLAGS_handrails;
  s.chair_rails = FLAGS_chair_rails;
  s.wainscot = FLAGS_wainscot;
  s.furniture = FLAGS_furniture;
  s.runner = FLAGS_runner;
  s.floor_stripes = FLAGS_floor_stripes;
  s.carpet = FLAGS_carpet;
  s.glass_walls = FLAGS_glass_walls;
  s.window_bands = FLAGS_window_bands;
  s.pillars = FLAGS_pillars;
  s.floor_gloss = FLAGS_floor_gloss;
  s.floor_gloss_reach = FLAGS_floor_gloss_reach;
  if (!s.Check(why)) return false;
  if (FLAGS_width_px < 16 || FLAGS_height_px < 16 || FLAGS_width_px > 8192 ||
      FLAGS_height_px > 8192) {
    *why = "image size must be within 16..8192 px";
    return false;
  }
  if (FLAGS_fx < 0 || !(FLAGS_hfov > 1 && FLAGS_hfov < 170)) {
    *why = "--fx must be >= 0 and --hfov within (1, 170)";
    return false;
  }
  preset->camera = Camera::FromHorizontalFov(FLAGS_width_px, FLAGS_height_px,
                                             FLAGS_hfov * M_PI / 180.0, FLAGS_camera_height);
  if (FLAGS_fx > 0) preset->camera.fx = preset->camera.fy = FLAGS_fx;
  if (!preset->camera.Check(why)) return false;
  if (FLAGS_frames < 1 || FLAGS_frames > 100000) {
    *why = "--frames must be in [1, 100000]";
    return false;
  }
  synth::SequenceOptions sequence;
  sequence.frames = FLAGS_preset == "single" ? 1 : FLAGS_frames;
  sequence.base = {FLAGS_pitch, FLAGS_yaw, FLAGS_offset, FLAGS_camera_height, FLAGS_distance,
                   FLAGS_roll};
  sequence.seed = FLAGS_seed;
  if (FLAGS_preset == "single") {
    sequence.yaw_amplitude = sequence.pitch_amplitude = sequence.offset_amplitude = 0;
  }
  const double last = FLAGS_distance + (sequence.frames - 1) * sequence.step;
  if (last > s.length - 3.0) {
    *why = "the sequence drives past the end wall: shorten --frames or lengthen --length";
    return false;
  }
  preset->poses = synth::MakeSequence(sequence);
  return true;
}

ToolInfo SynthToolInfo() {
  ToolInfo info;
  info.name = "corridor_synth";
  info.summary = "synthetic corridors with exact ground truth, in the dataset layout";
  info.usage =
      "corridor_synth --preset=paper --output_dir=D      (the paper's 9 scenes x 15 frames)\n"
      "corridor_synth --preset=sequence --frames=30 --corridor_width=2.5 --output_dir=D\n"
      "corridor_synth --preset=single --yaw=0.1 --pitch=0.05 --output_dir=D";
  info.flag_files = {"corridor_synth_main.cc"};
  for (const char* scene : {"paper_scale", "corridor_width", "ceiling_height", "length", "clutter",
                            "door_density", "contrast", "seed"}) {
    info.groups.emplace_back(scene, FlagGroup::kInput);
  }
  info.aliases = {{"hfov_deg", "hfov"}};
  return info;
}

int Main(int argc, char** argv) {
  int exit_code = 0;
  if (!ParseToolFlags(SynthToolInfo(), &argc, &argv, &exit_code)) return exit_code;
  if (argc > 1) return Usage(std::string("unexpected argument '") + argv[1] + "'");
  if (FLAGS_output_dir.empty()) return Usage("--output_dir is required");
  std::vector<synth::ScenePreset> presets;
  if (FLAGS_preset == "paper") {
    if (!(FLAGS_paper_scale >= 0.25 && FLAGS_paper_scale <= 8)) {
      return Usage("--paper_scale must be in [0.25, 8]");
    }
    presets = synth::PaperPreset(FLAGS_paper_scale);
  } else if (FLAGS_preset == "real_buildings") {
    synth::RealBuildingsOptions options;
    options.scenes = FLAGS_real_scenes;
    options.frames = FLAGS_real_frames;
    options.width_px = FLAGS_width_px;
    options.height_px = FLAGS_height_px;
    options.hfov_deg = FLAGS_hfov;
    const Status status = synth::RealBuildingsPreset(FLAGS_real_class, options, &presets);
    if (!status.ok()) return Usage(status.message());
  } else if (FLAGS_preset == "sequence" || FLAGS_preset == "single") {
    synth::ScenePreset preset;
    std::string why;
    if (!MakeCustomPreset(&preset, &why)) return Usage(why);
    presets.push_back(preset);
  } else {
    return Usage("unknown --preset '" + FLAGS_preset + "'; valid: paper, real_buildings, sequence, single");
  }
  int frames = 0;
  for (const auto& preset : presets) {
    Progress progress(preset.name, static_cast<int>(preset.poses.size()));
    const Status status = synth::WriteScene(FLAGS_output_dir, preset,
                                            [&](int done, int /*total*/) { progress.Tick(done); });
    progress.Finish();
    if (!status.ok()) return Usage(status.ToString());
    frames += static_cast<int>(preset.poses.size());
  }
  std::printf("corridor_synth: wrote %zu scene(s), %d frames to %s\n", presets.size(), frames,
              FLAGS_output_dir.c_str());
  return 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
