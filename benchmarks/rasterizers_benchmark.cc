// Time per depth image of each rasteriser at the paper's and common image sizes.
//   build/benchmarks/rasterizers_benchmark --benchmark_out=rasterizers.json

#include <benchmark/benchmark.h>

#include "corridor_depth/rasterizer.h"

namespace corridor {
namespace {

void BM_Rasterize(benchmark::State& state, const std::string& name, bool distorted) {
  const Camera camera = [&] {
    Camera c = Camera::FromHorizontalFov(static_cast<int>(state.range(0)),
                                         static_cast<int>(state.range(1)), 1.3, 0.66);
    if (distorted) c.distortion = {-0.2, 0.05, 0, 0, 0};
    return c;
  }();
  CorridorGeometry g;
  g.yaw = 0.08;
  g.pitch = 0.05;
  g.offset = 0.2;
  g.width = 2.4;
  g.camera_height = 0.66;
  std::unique_ptr<DepthRasterizer> rasterizer;
  if (!CreateRasterizer(name, RasterizerOptions(), &rasterizer).ok()) {
    state.SkipWithError("cannot create rasterizer");
    return;
  }
  cv::Mat depth;
  for (auto _ : state) {
    const Status status = rasterizer->Render(g, camera, &depth);
    benchmark::DoNotOptimize(status);
  }
}

#define SIZES ->Args({420, 360})->Args({640, 480})->Args({1280, 720})->Unit(benchmark::kMicrosecond)
BENCHMARK_CAPTURE(BM_Rasterize, exact, std::string("exact"), false)
SIZES;
BENCHMARK_CAPTURE(BM_Rasterize, exact_distorted, std::string("exact"), true)
SIZES;
BENCHMARK_CAPTURE(BM_Rasterize, paper, std::string("paper"), false)
SIZES;
#undef SIZES

}  // namespace
}  // namespace corridor
