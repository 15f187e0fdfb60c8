// Cost of guidance (guidance.hpp) for one anchor with N samples buffered: building the region's
// forecast (one O(N) pass, at the caller's rate) and ranking a candidate grid of 125 positions
// (O(1) each, plus the samples to certify of the 5 best). Budget (docs/guidance.md): 8 anchors at
// 1 Hz on one core within 1% of it, i.e. 10 ms for the 8 anchors' forecasts and rankings.
#include <benchmark/benchmark.h>

#include <vector>

#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/guidance.hpp"
#include "bench_data.hpp"

namespace {

namespace est = anchorbench::estimator;

est::RegionBasis Basis(const anchorbench::bench::PassByAnchor& data) {
  est::RegionBasis basis;
  basis.p_world_anchor = data.p_world_anchor;
  basis.noise_variance_m2 = 0.1 * 0.1;
  basis.travel_bias_m = 0.01;
  basis.region_chi2 = est::ChiSquare3Quantile(0.99);
  basis.accuracy_m = 0.1;  // tight, so that each of the best needs its search for samples
  return basis;
}

void BM_ForecastBuild(benchmark::State& state) {
  const auto data = anchorbench::bench::MakePassByAnchor(static_cast<std::size_t>(state.range(0)));
  const std::vector<int> tags(data.p_world_tag.size(), 0);
  const est::RegionBasis basis = Basis(data);
  for (auto _ : state) benchmark::DoNotOptimize(est::RegionForecast(basis, data.p_world_tag, tags).region_m());
}
BENCHMARK(BM_ForecastBuild)->Arg(1000)->Arg(10000);

void BM_RankGrid125(benchmark::State& state) {
  const auto data = anchorbench::bench::MakePassByAnchor(1000);
  const std::vector<int> tags(data.p_world_tag.size(), 0);
  const est::RegionForecast forecast(Basis(data), data.p_world_tag, tags);
  const std::vector<Eigen::Vector3d> grid = est::CandidateGrid(data.p_world_tag.back(), 2.0, 2);
  for (auto _ : state) benchmark::DoNotOptimize(forecast.Rank(grid, 50.0, 5));
}
BENCHMARK(BM_RankGrid125);

// The 1 Hz call for 8 anchors with 3000 samples each: 8 forecasts built and 8 grids ranked.
void BM_GuideEightAnchors(benchmark::State& state) {
  const auto data = anchorbench::bench::MakePassByAnchor(3000);
  const std::vector<int> tags(data.p_world_tag.size(), 0);
  const est::RegionBasis basis = Basis(data);
  const std::vector<Eigen::Vector3d> grid = est::CandidateGrid(data.p_world_tag.back(), 2.0, 2);
  for (auto _ : state) {
    for (int anchor = 0; anchor < 8; ++anchor) {
      benchmark::DoNotOptimize(est::RegionForecast(basis, data.p_world_tag, tags).Rank(grid, 50.0, 5));
    }
  }
}
BENCHMARK(BM_GuideEightAnchors)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
