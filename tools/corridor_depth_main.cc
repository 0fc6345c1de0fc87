// corridor_depth: dense metric depth from corridor images.
//   corridor_depth --input=PATH --output_dir=DIR [--camera=FILE] [--camera_height=M]
//                  [--solver=NAME] [--rasterizer=NAME] [--skip_existing]
// PATH is an image, a folder of images, or a dataset root. Writes, per scene,
// DIR/<scene>/depth/<frame>.png (16-bit mm, 0 = none), DIR/<scene>/vis/<frame>.png and
// DIR/<scene>/geometry.csv. Exit code 0: all frames ok; 1: some frames failed; 2: bad usage or
// configuration (also a camera whose size is not the first image's).

#include <cstdio>
#include <filesystem>
#include <map>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "io/camera_yaml.h"
#include "io/image_io.h"
#include "pipeline/confidence_mask.h"
#include "pipeline/floor_mask.h"
#include "pipeline/frame_pipeline.h"
#include "pipeline/recover_depth.h"
#include "pipeline/visualization.h"
#include "tools/geometry_csv.h"
#include "tools/input_source.h"
#include "tools/progress.h"
#include "tools/tool_flags.h"

DEFINE_string(input, "", "An image, a folder of images, or a dataset root");
DEFINE_string(output_dir, "", "Where the depth maps, pictures and geometry.csv go");
DEFINE_bool(write_vis, true, "Write DIR/<scene>/vis/<frame>.png (input with lines beside depth)");
DEFINE_double(vis_max_depth, 15.0, "Depth at the top of the colour scale in vis/, m");
DEFINE_bool(write_floor_mask, false,
            "Write DIR/<scene>/floor/<frame>.png: the floor the geometry predicts (255 = floor)");
DEFINE_bool(write_confidence, false,
            "Write DIR/<scene>/confidence/<frame>.png: 255 where the box model explains the image");
DEFINE_bool(skip_existing, false,
            "Resume: skip frames whose depth PNG and geometry.csv row are already in the output");

namespace corridor {
namespace {

namespace fs = std::filesystem;

int Usage(const std::string& message) {
  std::fprintf(stderr, "corridor_depth: %s\n", message.c_str());
  return 2;
}

// Writes one frame's outputs and its geometry row.
Status WriteFrame(const fs::path& scene_dir, const PipelineFrame& frame, GeometryCsv* csv) {
  const RecoverDepthResult& result = frame.result;
  if (result.has_geometry) {
    csv->Add(frame.name, result);
  } else {
    csv->AddFailure(frame.name, result.status);
  }
  if (!result.depth.empty()) {
    const Status status =
        WriteDepthPng((scene_dir / "depth" / (frame.name + ".png")).string(), result.depth);
    if (!status.ok()) return status;
    if (FLAGS_write_floor_mask) {
      const Status written =
          WriteImageAtomic((scene_dir / "floor" / (frame.name + ".png")).string(),
                           PredictFloorMask(*frame.camera, result.geometry, FLAGS_max_range));
      if (!written.ok()) return written;
    }
    if (FLAGS_write_confidence && !result.image.empty()) {
      const Status written = WriteImageAtomic(
          (scene_dir / "confidence" / (frame.name + ".png")).string(),
          ComputeConfidenceMask(result.image, result.depth, *frame.camera, result.geometry));
      if (!written.ok()) return written;
    }
  }
  if (FLAGS_write_vis && !frame.image.empty()) {
    return WriteImageAtomic((scene_dir / "vis" / (frame.name + ".png")).string(),
                            MakeResultPanel(frame.image, result, FLAGS_vis_max_depth));
  }
  return Status::Ok();
}

// --skip_existing: the geometry.csv rows of the frames whose depth PNG an earlier run wrote, by
// scene order (empty = compute the frame). A frame without its row is computed again.
Status KeptRows(const InputScene& scene, const fs::path& scene_dir,
                std::vector<std::string>* kept) {
  kept->assign(scene.frames.size(), "");
  if (!FLAGS_skip_existing) return Status::Ok();
  std::map<std::string, std::string> rows;
  const Status status = ReadGeometryCsvRows((scene_dir / "geometry.csv").string(), &rows);
  if (status.code() == StatusCode::kNotFound) return Status::Ok();
  if (!status.ok()) return status;
  for (size_t i = 0; i < scene.frames.size(); ++i) {
    const auto row = rows.find(scene.frames[i].name);
    std::error_code ec;
    if (row != rows.end() && fs::exists(scene_dir / "depth" / (row->first + ".png"), ec)) {
      (*kept)[i] = row->second;
    }
  }
  return Status::Ok();
}

// Processes one scene through the two-thread pipeline; returns the number of failed frames, or
// -1 when an output cannot be written (which stops the run: nothing more could be saved).
int RunScene(const InputScene& scene, const DepthRecoverer& recoverer, const std::string& out,
             int* skipped) {
  const fs::path scene_dir = fs::path(out) / scene.name;
  const std::string csv_path = (scene_dir / "geometry.csv").string();
  std::vector<std::string> kept;
  Status write_error = KeptRows(scene, scene_dir, &kept);
  // The camera that was used (from a file, or from --fx/--hfov), so that every run records it.
  if (write_error.ok()) {
    write_error = WriteCameraYaml((scene_dir / "camera_used.yaml").string(), scene.camera);
  }
  if (!write_error.ok()) {
    std::fprintf(stderr, "corridor_depth: --skip_existing: %s\n", write_error.ToString().c_str());
    return -1;
  }
  std::vector<size_t> todo;  // The frames to compute, by index into scene.frames.
  for (size_t i = 0; i < kept.size(); ++i) {
    if (kept[i].empty()) todo.push_back(i);
  }
  *skipped = static_cast<int>(scene.frames.size() - todo.size());
  const int total = static_cast<int>(todo.size());
  std::vector<std::string> rows = kept;  // geometry.csv rows in scene order; "" = none yet.
  const auto write_csv = [&]() {
    GeometryCsv csv;
    for (const auto& row : rows) {
      if (!row.empty()) csv.AddRow(row);
    }
    return WriteTextAtomic(csv_path, csv.Text());
  };
  Progress progress(scene.name, total);
  int failed = 0;
  size_t next = 0;
  const auto source = [&](PipelineFrame* frame) {
    if (next >= todo.size()) return false;
    const DatasetFrame& input = scene.frames[todo[next++]];
    frame->name = input.name;
    frame->camera = &scene.camera;
    frame->read_status = ReadColorImage(input.rgb_path, &frame->image);
    return true;
  };
  const auto sink = [&](PipelineFrame&& frame) {
    const size_t index = todo[frame.index];
    if (!frame.result.status.ok()) {
      ++failed;
      std::fprintf(stderr, "%sframe %s failed: %s\n", total > 1 ? "\n" : "",
                   scene.frames[index].rgb_path.c_str(), frame.result.status.ToString().c_str());
    }
    GeometryCsv row;
    write_error = WriteFrame(scene_dir, frame, &row);
    rows[index] = row.rows().front();
    const bool last = frame.index + 1 == total;
    if (write_error.ok() && (last || (frame.index + 1) % 50 == 0)) write_error = write_csv();
    progress.Tick(static_cast<int>(frame.index + 1));
    return write_error.ok();
  };
  FramePipeline(recoverer).Run(source, sink);
  progress.Finish();
  if (total == 0) write_error = write_csv();  // Every frame was kept: the CSV as it was.
  if (!write_error.ok()) {
    std::fprintf(stderr, "corridor_depth: cannot write output: %s\n",
                 write_error.ToString().c_str());
    return -1;
  }
  return failed;
}

int Main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "corridor_depth --input=PATH --output_dir=DIR [--camera=FILE] [--camera_height=M] "
      "[--solver=NAME] [--rasterizer=NAME] [--skip_existing]");
  const Status flags = CheckFlagNames(argc, argv);
  if (!flags.ok()) return Usage(flags.message());
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  if (argc > 1) return Usage(std::string("unexpected argument '") + argv[1] + "'");
  if (FLAGS_input.empty()) return Usage("--input is required (an image, a folder or a dataset)");
  if (FLAGS_output_dir.empty()) return Usage("--output_dir is required");
  if (!(FLAGS_vis_max_depth > 0)) return Usage("--vis_max_depth must be positive");

  RecoverDepthOptions options;
  Status status = RecoverDepthOptionsFromFlags(&options);
  if (!status.ok()) return Usage(status.message());
  std::unique_ptr<DepthRecoverer> recoverer;
  status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) return Usage(status.message());
  std::vector<InputScene> scenes;
  status = ResolveInput(FLAGS_input, CameraOverridesFromFlags(), &scenes);
  if (!status.ok()) return Usage(status.message());
  for (const auto& scene : scenes) {
    status = CheckFirstFrameSize(scene);
    if (!status.ok()) return Usage(status.message());
  }

  int failed = 0, total = 0, skipped = 0;
  for (const auto& scene : scenes) {
    int scene_skipped = 0;
    const int scene_failed = RunScene(scene, *recoverer, FLAGS_output_dir, &scene_skipped);
    if (scene_failed < 0) return 2;
    failed += scene_failed;
    skipped += scene_skipped;
    total += static_cast<int>(scene.frames.size());
  }
  std::printf("corridor_depth: %d of %d frames ok, %d of them kept from an earlier run "
              "(solver %s, rasterizer %s); outputs in %s\n",
              total - failed, total, skipped, options.solver.c_str(), options.rasterizer.c_str(),
              FLAGS_output_dir.c_str());
  return failed > 0 ? 1 : 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
