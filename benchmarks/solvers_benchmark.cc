// Time per solve of every solver on the same junction points (exact, and with 1 px noise).
//   build/benchmarks/solvers_benchmark --benchmark_out=solvers.json

#include <random>

#include <benchmark/benchmark.h>

#include "corridor_depth/solver.h"
#include "tests/support/exact_observation.h"

namespace corridor {
namespace {

CorridorObservation BenchObservation(double noise_px) {
  CorridorObservation obs = testing::ExactObservation(
      testing::MakeGeometry(0.08, 0.05, 0.2, 2.4, 0.62), 30, 1.5, 15.0);
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, noise_px);
  if (noise_px > 0) {
    for (auto* side : {&obs.left, &obs.right}) {
      for (auto& p : *side) p += Eigen::Vector2d(noise(rng), noise(rng));
    }
  }
  return obs;
}

void BM_Solve(benchmark::State& state, const std::string& name, double noise_px) {
  std::unique_ptr<CorridorSolver> solver;
  if (!CreateSolver(name, SolverOptions(), &solver).ok()) {
    state.SkipWithError("cannot create solver");
    return;
  }
  const CorridorObservation obs = BenchObservation(noise_px);
  SolverSummary summary;
  for (auto _ : state) {
    const Status status = solver->Solve(obs, nullptr, &summary);
    benchmark::DoNotOptimize(status);
  }
  state.counters["evaluations"] = summary.evaluations;
  state.counters["width_error_mm"] = 1000 * std::abs(summary.estimate.width - 2.4);
}

BENCHMARK_CAPTURE(BM_Solve, grid_exact, std::string("grid"), 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, lm_exact, std::string("lm"), 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, closed_form_exact, std::string("closed_form"), 0.0)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, closed_form_lm_exact, std::string("closed_form+lm"), 0.0)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, joint_exact, std::string("joint"), 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, joint_noise1px, std::string("joint"), 1.0)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, grid_noise1px, std::string("grid"), 1.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, lm_noise1px, std::string("lm"), 1.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, closed_form_noise1px, std::string("closed_form"), 1.0)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, closed_form_lm_noise1px, std::string("closed_form+lm"), 1.0)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace corridor
