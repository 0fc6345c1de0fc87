// corridor_depth: dense metric depth from corridor images.
//   corridor_depth --input=PATH --output_dir=DIR [--camera=FILE] [--camera_height=M]
//                  [--solver=NAME] [--rasterizer=NAME]
// PATH is an image, a folder of images, or a dataset root. Writes, per scene,
// DIR/<scene>/depth/<frame>.png (16-bit mm, 0 = none), DIR/<scene>/vis/<frame>.png and
// DIR/<scene>/geometry.csv. Exit code 0: all frames ok; 1: some frames failed; 2: bad usage.

#include <cstdio>
#include <filesystem>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "io/image_io.h"
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
  }
  if (FLAGS_write_vis && !frame.image.empty()) {
    return WriteImageAtomic((scene_dir / "vis" / (frame.name + ".png")).string(),
                            MakeResultPanel(frame.image, result, FLAGS_vis_max_depth));
  }
  return Status::Ok();
}

// Processes one scene through the two-thread pipeline; returns the number of failed frames, or
// -1 when an output cannot be written (which stops the run: nothing more could be saved).
int RunScene(const InputScene& scene, const DepthRecoverer& recoverer, const std::string& out) {
  const fs::path scene_dir = fs::path(out) / scene.name;
  const std::string csv_path = (scene_dir / "geometry.csv").string();
  const int total = static_cast<int>(scene.frames.size());
  GeometryCsv csv;
  Progress progress(scene.name, total);
  int failed = 0;
  size_t next = 0;
  Status write_error = Status::Ok();
  const auto source = [&](PipelineFrame* frame) {
    if (next >= scene.frames.size()) return false;
    const DatasetFrame& input = scene.frames[next++];
    frame->name = input.name;
    frame->camera = &scene.camera;
    frame->read_status = ReadColorImage(input.rgb_path, &frame->image);
    return true;
  };
  const auto sink = [&](PipelineFrame&& frame) {
    if (!frame.result.status.ok()) {
      ++failed;
      std::fprintf(stderr, "%sframe %s failed: %s\n", total > 1 ? "\n" : "",
                   scene.frames[frame.index].rgb_path.c_str(),
                   frame.result.status.ToString().c_str());
    }
    write_error = WriteFrame(scene_dir, frame, &csv);
    const bool last = frame.index + 1 == total;
    if (write_error.ok() && (last || csv.size() % 50 == 0)) {
      write_error = WriteTextAtomic(csv_path, csv.Text());
    }
    progress.Tick(static_cast<int>(frame.index + 1));
    return write_error.ok();
  };
  FramePipeline(recoverer).Run(source, sink);
  progress.Finish();
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
      "[--solver=NAME] [--rasterizer=NAME]");
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

  int failed = 0, total = 0;
  for (const auto& scene : scenes) {
    const int scene_failed = RunScene(scene, *recoverer, FLAGS_output_dir);
    if (scene_failed < 0) return 2;
    failed += scene_failed;
    total += static_cast<int>(scene.frames.size());
  }
  std::printf("corridor_depth: %d of %d frames ok (solver %s, rasterizer %s); outputs in %s\n",
              total - failed, total, options.solver.c_str(), options.rasterizer.c_str(),
              FLAGS_output_dir.c_str());
  return failed > 0 ? 1 : 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
