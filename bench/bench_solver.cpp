// LS (Eqs. (9)-(10)) + NLS (Eqs. (11)-(13)) on N samples: the work per iteration must grow
// linearly in N. bench_compare runs every registered solver on the same data, side by side.
#include <benchmark/benchmark.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "bench_data.hpp"

namespace {

using anchorbench::estimator::AnchorSolver;
using anchorbench::estimator::AnchorSolverOptions;
using anchorbench::estimator::KernelMode;

void Solve(benchmark::State& state, KernelMode kernel) {
  const auto data = anchorbench::bench::MakePassByAnchor(static_cast<std::size_t>(state.range(0)));
  AnchorSolverOptions options;
  options.nls.kernel = kernel;
  const AnchorSolver solver(options);
  int iterations = 0;
  for (auto _ : state) {
    const auto result = solver.Solve(data.p_world_tag, data.range_m);
    iterations = result.iterations;
    benchmark::DoNotOptimize(result);
  }
  state.counters["lm_iterations"] = iterations;
}

void BM_LsAdaptiveNls(benchmark::State& state) { Solve(state, KernelMode::kAdaptive); }
void BM_LsL2Nls(benchmark::State& state) { Solve(state, KernelMode::kL2); }

BENCHMARK(BM_LsAdaptiveNls)->Arg(600)->Arg(2400)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LsL2Nls)->Arg(600)->Arg(2400)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
