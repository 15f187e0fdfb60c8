// Cost of one trigger update with N samples buffered (Figs. 7/8, "compute time per update"):
// the closest-point PDOP is O(1) per sample; the PDOP at the LS or NLS estimate needs that solve
// on all N samples plus an O(N) pass for Eq. (3), at every update.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/eval/true_geometry.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace {

namespace est = anchorbench::estimator;

struct Data {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> d;
  Eigen::Vector3d p_anchor{0, 4, 3};
};

Data MakeData(std::size_t n) {
  anchorbench::sim::RandomStream rng(2, 0, anchorbench::sim::kFirstFreeStreamId);
  Data data;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 60.0 * static_cast<double>(k) / static_cast<double>(n);
    const Eigen::Vector3d p(-30.0 + t, 2.0 * std::sin(0.3 * t), 1.5 + std::sin(0.17 * t));
    data.p.push_back(p);
    data.d.push_back((p - data.p_anchor).norm() + 0.1 + 0.1 * rng.Normal());
  }
  return data;
}

void BM_UpdateClosestPoint(benchmark::State& state) {
  const Data data = MakeData(static_cast<std::size_t>(state.range(0)));
  est::ClosestPointPdop pdop;
  for (std::size_t k = 0; k + 1 < data.p.size(); ++k) pdop.Add(data.p[k], data.d[k]);
  for (auto _ : state) {
    est::ClosestPointPdop copy = pdop;  // one more sample onto N - 1
    copy.Add(data.p.back(), data.d.back());
    benchmark::DoNotOptimize(copy.Value());
  }
}

void BM_UpdateLsPdop(benchmark::State& state) {
  const Data data = MakeData(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const est::SolveResult ls = est::SolveDoubleDifferenceLs(data.p, data.d);
    benchmark::DoNotOptimize(est::GeometryPdop(data.p, data.d, ls.p_world_anchor));
  }
}

void BM_UpdateNlsPdop(benchmark::State& state) {
  const Data data = MakeData(static_cast<std::size_t>(state.range(0)));
  const est::AnchorSolver solver;
  for (auto _ : state) {
    const est::SolveResult nls = solver.Solve(data.p, data.d);
    benchmark::DoNotOptimize(est::GeometryPdop(data.p, data.d, nls.p_world_anchor));
  }
}

void BM_UpdateTruePdop(benchmark::State& state) {  // the oracle (eval), its running sums: O(1)
  const Data data = MakeData(static_cast<std::size_t>(state.range(0)));
  anchorbench::eval::TrueGeometry truth(data.p_anchor);
  for (std::size_t k = 0; k + 1 < data.p.size(); ++k) truth.Add(data.p[k]);
  for (auto _ : state) {
    anchorbench::eval::TrueGeometry copy = truth;  // one more sample onto N - 1
    copy.Add(data.p.back());
    benchmark::DoNotOptimize(copy.Pdop());
  }
}

BENCHMARK(BM_UpdateClosestPoint)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK(BM_UpdateLsPdop)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UpdateNlsPdop)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UpdateTruePdop)->Arg(100)->Arg(1000)->Arg(10000);

}  // namespace

BENCHMARK_MAIN();
