// LS (Eqs. (9)-(10)) + NLS (Eqs. (11)-(13)) on N samples: the work per iteration must grow
// linearly in N. Targets (issue 2): LS + adaptive NLS on 600 samples < 0.3 ms, on 1e4 < 5 ms.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace {

using anchorbench::estimator::AnchorSolver;
using anchorbench::estimator::AnchorSolverOptions;
using anchorbench::estimator::KernelMode;

struct Data {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> d;
};

// A tunnel-like pass by a wall anchor at 10 Hz, sigma_d = 0.1 m, 5% NLOS outliers.
Data MakeData(std::size_t n) {
  anchorbench::sim::RandomStream rng(1, 0, anchorbench::sim::kFirstFreeStreamId);
  Data data;
  const Eigen::Vector3d p_anchor(0, 4, 3);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 60.0 * static_cast<double>(k) / static_cast<double>(n);
    const Eigen::Vector3d p(-30.0 + t, 2.0 * std::sin(0.3 * t), 1.5 + std::sin(0.17 * t));
    double d = (p - p_anchor).norm() + 0.2 + 0.1 * rng.Normal();
    if (rng.Uniform() < 0.05) d += rng.Uniform(1.0, 10.0);
    data.p.push_back(p);
    data.d.push_back(d);
  }
  return data;
}

void Solve(benchmark::State& state, KernelMode kernel) {
  const Data data = MakeData(static_cast<std::size_t>(state.range(0)));
  AnchorSolverOptions options;
  options.nls.kernel = kernel;
  const AnchorSolver solver(options);
  int iterations = 0;
  for (auto _ : state) {
    const auto result = solver.Solve(data.p, data.d);
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
