// The joint solve allocates nothing once warm: this binary counts every global operator new, and
// a second solve of the same observation (from a given start and from the closed form) must not
// call it.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "estimation/joint_solver.h"
#include "tests/support/exact_observation.h"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// Not inlined: inlined into a caller, GCC sees free() on operator new's pointer and warns
// (-Wmismatched-new-delete), though the two replacements match.
__attribute__((noinline)) void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace corridor {
namespace {

TEST(JointSolverAllocationTest, ASteadyStateSolveAllocatesNothing) {
  for (const char* loss : {"none", "huber", "cauchy"}) {
    SolverOptions options;
    options.loss = loss;
    const JointSolver solver(options);
    const CorridorGeometry truth = testing::MakeGeometry(0.12, 0.06, 0.25, 2.4, 0.62);
    CorridorObservation obs = testing::ExactObservation(truth, 30);
    obs.left[4].y() += 25;  // an outlier, so that the loss matters
    const CorridorGeometry start = testing::MakeGeometry(0.05, 0.0, 0.0, 2.0, 0.62);
    SolverSummary summary;
    const CorridorGeometry* const starts[] = {&start, nullptr};
    for (const CorridorGeometry* initial : starts) {
      ASSERT_TRUE(solver.Solve(obs, initial, &summary).ok());  // warm-up
      const long before = allocations.load();
      ASSERT_TRUE(solver.Solve(obs, initial, &summary).ok());
      EXPECT_EQ(allocations.load() - before, 0) << loss << (initial ? " from a start" : "");
      EXPECT_GT(summary.iterations, 1) << loss;
    }
  }
}

}  // namespace
}  // namespace corridor
