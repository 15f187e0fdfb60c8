// Streaming closest-point PDOP (Eq. (4)): cost per sample must stay flat from 1e2 to 1e6 samples.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "anchorbench/estimator/closest_point_pdop.hpp"

namespace {

void BM_ClosestPointPdopPerSample(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<Eigen::Vector3d> p(n);
  std::vector<double> d(n);
  const Eigen::Vector3d p_anchor(0, 4, 3);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 0.1 * static_cast<double>(k);
    p[k] = Eigen::Vector3d(-50.0 + 1e-4 * t, 2.0 * std::sin(0.3 * t), 1.5 + std::sin(0.17 * t));
    d[k] = (p[k] - p_anchor).norm();
  }
  for (auto _ : state) {
    anchorbench::estimator::ClosestPointPdop pdop;
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      pdop.Add(p[k], d[k]);
      sum += pdop.Value();  // the trigger reads it after every sample
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(n));
}
BENCHMARK(BM_ClosestPointPdopPerSample)->RangeMultiplier(10)->Range(100, 1000000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
